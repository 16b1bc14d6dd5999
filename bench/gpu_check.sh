#!/usr/bin/env bash
# The GPU check of the `opencl` backend, in one run of a few minutes (docs/opencl-backend.md,
# "Checking on a GPU").
#
# A machine lent with an NVIDIA GPU often has no package registry, so it can neither install
# the project's dependencies nor build it. The check therefore comes in two halves:
#
#   on a Debian 12 machine, after a release build:   bench/gpu_check.sh --pack DIR
#     copies `collide`, the OpenCL test programs, the scene library and every shared library
#     they load into DIR, with this script. Left out: the C library and the dynamic loader
#     (the GPU machine's own must load the programs) and the vendors' OpenCL drivers (the
#     ICDs: the GPU machine's driver is the point); the ICD loader libOpenCL.so.1 is carried.
#
#   on the GPU machine:                               DIR/gpu_check.sh
#     1. finds the NVIDIA OpenCL ICD: a *.icd file naming NVIDIA in /etc/OpenCL/vendors, or
#        the driver's libnvidia-opencl.so.1 (ldconfig -p), registered for this run alone in a
#        vendors folder of the results (OCL_ICD_VENDORS), never in /etc;
#     2. lists the devices and picks one (--device, default NVIDIA);
#     3. runs the OpenCL test programs on it (COLLIDE_CL_DEVICE);
#     4. runs every scene of the library on `cpu` (host) and `opencl` (float, the device) and
#        compares every position and velocity of every output frame bit for bit; where they
#        differ it reruns to name the cause (the order of the sums, or the float operations
#        of the device) and reports the largest difference;
#     5. runs `collide bench opencl` at N = 1e4, 1e6 and 4e6 and prints the disk-steps per
#        second against the target, >= 1e9 at N = 4e6 (judged on a GPU only).
#
# Every step has a time limit (together under 6 minutes) and prints its elapsed time. All
# output goes to one results folder (--out): check.log (what was printed), summary.txt,
# devices.txt, tests/, bits/, bench-opencl.csv and .json. Exit status: 0 when everything ran
# and the tests passed (bits that differ and a target not met are findings, reported, not
# failures); 1 when a test program failed or a step ran out of time; 2 when the check cannot
# start (no bundle, no NVIDIA ICD, no device, a bad option).
# shellcheck disable=SC2317  # the steps' functions are called through step(), which shellcheck cannot follow
set -euo pipefail

readonly target_disk_steps=1e9 target_size=4000000
# Time limits in seconds (the devices' for each of two listings); their sum stays under 6 minutes.
readonly limit_devices=10 limit_tests=110 limit_bits=80 limit_bench=140

usage() {
    cat <<'EOF'
usage: bench/gpu_check.sh --pack DIR [--build BUILD]
       DIR/gpu_check.sh [--bundle DIR] [--device TEXT] [--nvidia-library PATH] [--sizes N,N,...]
                        [--steps N] [--scenes NAME,NAME,...] [--out DIR]
  --pack DIR      make the bundle DIR from a release build (on the build machine)
  --build BUILD   the build to pack (default: build/release of this source tree)
  --bundle DIR    the bundle to check (default: the folder this script is in)
  --device TEXT   OpenCL device: an index of `collide devices`, or a case-insensitive piece of
                  "platform: device" (default NVIDIA; a platform's name picks its first
                  device). A selector naming NVIDIA requires the NVIDIA ICD.
  --nvidia-library PATH
                  the driver's libnvidia-opencl.so.1 where the check does not find it: it is
                  registered for this run (OCL_ICD_VENDORS) whatever else is installed
  --sizes LIST    disk counts of the benchmark (default 10000,1000000,4000000)
  --steps N       most timed steps per benchmark case (default 100)
  --scenes LIST   scenes of the library compared bit for bit (default: all of them)
  --out DIR       the results folder (default gpu-check-results-DATE in the current folder)
       bench/gpu_check.sh --compare A.xyz B.xyz
                  compare two runs' frames (collide export -o NAME.xyz) as step 4 does
EOF
}

# A check that cannot go on says why, in the summary too once the results folder exists.
fail() {
    echo "gpu_check: $*" >&2
    if [[ ${results_ready:-0} == 1 ]]; then echo "failed: $*" >> "$out/summary.txt"; fi
    exit 2
}
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }
# Seconds left before a deadline (at least 1, so that `timeout` always gets a valid limit).
left() { awk -v d="$1" -v n="$(now)" 'BEGIN { s = int(d - n); print (s < 1 ? 1 : s) }'; }
# The time SECONDS from now, to the millisecond. (awk's plain `print` of a sum writes 6
# significant digits, so an epoch time would come out rounded by up to 5000 s.)
deadline_in() { awk -v n="$(now)" -v l="$1" 'BEGIN { printf "%.3f", n + l }'; }

# ---------------------------------------------------------------------------------------------
# Packing (on the build machine)

# The C library and the dynamic loader belong to the machine that runs the programs.
readonly system_libraries='^(linux-vdso|libc|libm|libdl|libpthread|librt|libresolv|libutil|ld-linux[^ ]*)\.so'

copy_libraries_of() {  # PROGRAM LIBDIR
    local name path
    if ldd "$1" | grep -q 'not found'; then
        ldd "$1" | grep 'not found' >&2
        fail "--pack: $1 needs libraries this machine lacks (above); install them or rebuild"
    fi
    while read -r name path; do
        grep -Eq "$system_libraries" <<< "$name" || cp -L -n "$path" "$2/$name"
    done < <(ldd "$1" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }')
}

pack() {  # BUILD DIR
    local build=$1 dir=$2 program tests=()
    [[ -x "$build/collide" ]] || fail "--pack: no program '$build/collide': build it first (cmake --preset release && cmake --build build/release)"
    for program in "$build"/tests/opencl/test_opencl_*; do
        [[ -f $program && -x $program ]] && tests+=("$program")  # not CTest's *.cmake files beside them
    done
    [[ ${#tests[@]} -gt 0 ]] || fail "--pack: no OpenCL test programs in '$build/tests/opencl': build them (cmake --build $build)"
    [[ ! -e "$dir" || -z "$(ls -A "$dir")" ]] || fail "--pack: '$dir' exists and is not empty; name a new folder"
    mkdir -p "$dir/bin" "$dir/lib" "$dir/tests" "$dir/share/collide/data"
    cp "$build/collide" "$dir/bin/"
    cp "${tests[@]}" "$dir/tests/"
    # `collide` finds its scene library at ../share/collide beside bin/ (apps/resource_path.cpp).
    cp -r "$source_dir/data/scenes" "$dir/share/collide/data/"
    cp "$script_path" "$dir/gpu_check.sh"
    for program in "$dir/bin/collide" "$dir"/tests/*; do copy_libraries_of "$program" "$dir/lib"; done
    [[ -e "$dir/lib/libOpenCL.so.1" ]] || fail "--pack: the OpenCL ICD loader libOpenCL.so.1 is not among the libraries of $build/collide"
    {
        echo "commit: $(git -C "$source_dir" describe --always --dirty 2>/dev/null || echo unknown)"
        echo "packed: $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -m)"
        echo "glibc: $(getconf GNU_LIBC_VERSION | awk '{ print $2 }')"
    } > "$dir/bundle.txt"
    echo "gpu_check: packed $dir ($(du -sh "$dir" | cut -f1)): carry it to the GPU machine and run $dir/gpu_check.sh there"
}

# ---------------------------------------------------------------------------------------------
# The check (on the GPU machine)

check_bundle() {
    [[ -x "$bundle/bin/collide" && -f "$bundle/bundle.txt" ]] ||
        fail "no bundle at '$bundle' (bin/collide, bundle.txt): make one with bench/gpu_check.sh --pack DIR on the build machine"
    local built here
    built=$(awk '$1 == "glibc:" { print $2 }' "$bundle/bundle.txt")
    here=$(getconf GNU_LIBC_VERSION | awk '{ print $2 }')
    if [[ -n "$built" && "$(printf '%s\n%s\n' "$built" "$here" | sort -V | head -1)" != "$built" ]]; then
        fail "this machine's C library (glibc $here) is older than the build machine's (glibc $built): the carried programs cannot load here"
    fi
    export LD_LIBRARY_PATH="$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
}

# The ICD loader reads the vendors' *.icd files from OCL_ICD_VENDORS, else /etc/OpenCL/vendors.
# A driver installed without its ICD file is registered in a vendors folder of the results.
find_nvidia_icd() {
    local vendors=${OCL_ICD_VENDORS:-/etc/OpenCL/vendors} icd lib=$nvidia_library ldconfig
    if [[ -n $lib ]]; then
        [[ -f $lib ]] || fail "--nvidia-library: no file '$lib'"
        register_icd "$lib" "$vendors"; return
    fi
    icd=$(grep -lis nvidia "$vendors"/*.icd 2>/dev/null | head -1 || true)
    if [[ -n "$icd" ]]; then echo "NVIDIA ICD: $icd ($(head -1 "$icd"))"; return; fi
    if [[ -n "${OCL_ICD_VENDORS:-}" ]]; then
        fail "no NVIDIA OpenCL ICD: OCL_ICD_VENDORS=$OCL_ICD_VENDORS holds no *.icd file naming NVIDIA; unset it to let the check look in /etc/OpenCL/vendors and for libnvidia-opencl.so.1, name the library with --nvidia-library, or pass --device to check another device"
    fi
    ldconfig=$(command -v ldconfig || echo /sbin/ldconfig)
    lib=$("$ldconfig" -p 2>/dev/null | awk '$1 == "libnvidia-opencl.so.1" && /x86-64/ { print $NF; exit }' || true)
    for icd in /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1 /usr/lib64/libnvidia-opencl.so.1 \
               /usr/local/nvidia/lib64/libnvidia-opencl.so.1; do
        [[ -n "$lib" ]] && break
        [[ -e "$icd" ]] && lib=$icd
    done
    [[ -n "$lib" ]] || fail "no NVIDIA OpenCL ICD: $vendors has no *.icd file naming NVIDIA, and libnvidia-opencl.so.1 is neither in 'ldconfig -p' nor in /usr/lib/x86_64-linux-gnu, /usr/lib64 or /usr/local/nvidia/lib64. Install the NVIDIA driver's OpenCL part (Debian: nvidia-opencl-icd), name the library with --nvidia-library, or pass --device to check another OpenCL device"
    register_icd "$lib" "$vendors"
}

register_icd() {  # LIBRARY VENDORS: the library as nvidia.icd beside copies of VENDORS' files
    mkdir -p "$out/vendors"
    cp "$2"/*.icd "$out/vendors/" 2>/dev/null || true  # keep the other devices listed
    echo "$1" > "$out/vendors/nvidia.icd"
    export OCL_ICD_VENDORS="$out/vendors"
    echo "NVIDIA ICD: $1, registered for this run (OCL_ICD_VENDORS=$OCL_ICD_VENDORS)"
}

# Step 2: the device. Sets device_type (GPU, CPU, ...) and device_line.
pick_device() {
    timeout "$limit_devices" "$collide" devices > "$out/devices.txt" 2>&1 ||
        { cat "$out/devices.txt" >&2; fail "collide devices found no OpenCL device (above)"; }
    cat "$out/devices.txt"
    local picked
    picked=$(timeout "$limit_devices" "$collide" devices --cl-device "$device" 2>&1) ||
        { echo "$picked" >&2; fail "no OpenCL device matches --device '$device' (above)"; }
    device_line=$(grep -E '^\s*\[[0-9]+\]' <<< "$picked" | sed 's/^\s*//')
    device_float=$(grep -E '^\s*float:' <<< "$picked" | sed 's/^\s*//')
    device_type=$(sed -E 's/.*\((GPU|CPU|accelerator|other), .*/\1/' <<< "$device_line")
    echo "picked: $device_line"
    summary "device: $device_line; $device_float"
    if [[ ${device,,} == *nvidia* && $device_type != GPU ]]; then
        fail "the device matching '$device' is not a GPU: $device_line"
    fi
}

# Step 3: the OpenCL test programs, run directly (the carried bundle has no CTest files).
run_tests() {
    local deadline program name passed=0 failed=() code
    deadline=$(deadline_in "$limit_tests")
    mkdir -p "$out/tests"
    for program in "$bundle"/tests/test_opencl_*; do
        name=${program##*/}
        code=0
        COLLIDE_CL_DEVICE=$device timeout "$(left "$deadline")" "$program" --gtest_brief=1 \
            > "$out/tests/$name.log" 2>&1 || code=$?
        if [[ $code == 0 ]]; then
            passed=$((passed + 1)); echo "passed: $name ($(grep -o 'PASSED.*' "$out/tests/$name.log" | head -1))"
        elif [[ $code == 124 ]]; then
            failed+=("$name"); status=1; echo "FAILED: $name (stopped at the step's time limit; see tests/$name.log)"
        else
            failed+=("$name"); status=1; echo "FAILED: $name (see tests/$name.log)"
        fi
    done
    summary "tests: $passed passed, ${#failed[@]} failed${failed[*]:+: ${failed[*]}}"
}

# Compares two runs' frames (extended XYZ from `collide export`): positions and velocities of
# every disk at every output time. Prints "equal VALUES", "differ frames" (other numbers of
# frames or disks), or "differ COUNT VALUES" followed by two differences, the first one met
# (where the rounding entered) and the largest one (what it grew to), each as "|DIFFERENCE|
# QUANTITY DISK TIME ULPS": ULPS in units of the float spacing at the value, 2^(e-23) for a
# value in [2^e, 2^(e+1)).
# shellcheck disable=SC2016  # an awk program: its $ are awk's
readonly compare_frames='
    function ulps(d, a,    e) {
        if (a < 0) a = -a
        e = a > 0 ? int(log(a) / log(2) + 1e-9) : -126
        if (2 ^ e > a) --e
        return d / 2 ^ (e - 23)
    }
    function describe(d, k, a) { return sprintf("%.3g %s %d %s %.3g", d, name[k], disk, t, ulps(d, a)) }
    BEGIN { split("x y vx vy", name, " "); split("2 3 7 8", column, " ") }
    {
        if ((getline other < second) <= 0) { unequal_frames = 1; exit }
        if (FNR == 1 || disk == count) { count = $1; disk = -1; next }
        if (disk == -1) { t = $0; sub(/.* Time=/, "", t); disk = 0; next }
        split(other, b, " ")
        for (k = 1; k <= 4; ++k) {
            ++values
            a = $(column[k]) + 0; d = a - b[column[k]]; if (d < 0) d = -d
            if (d == 0) continue
            if (!differing++) first = describe(d, k, a)
            if (d > largest) { largest = d; worst = describe(d, k, a) }
        }
        ++disk
    }
    END {
        if (unequal_frames || (!differing && (getline other < second) > 0)) print "differ frames"
        else if (!differing) print "equal", values
        else print "differ", differing, values, first, worst
    }'

# Runs SCENE on BACKEND (more `collide run` options after) and exports its frames to
# WORK/NAME.xyz. Fails with the run's message on stderr.
run_frames() {  # NAME SCENE BACKEND [OPTIONS...]
    local name=$1 scene=$2 backend=$3
    shift 3
    timeout "$(left "$bits_deadline")" "$collide" run "$scene" --backend "$backend" --frames -o "$work/$name.h5" "$@" \
        > "$work/$name.txt" 2>&1 || { tail -1 "$work/$name.txt" >&2; return 1; }
    "$collide" export "$work/$name.h5" -o "$work/$name.xyz" > /dev/null
    rm -f "$work/$name.h5"
}

compare_files() { awk -v second="$2" "$compare_frames" "$1"; }
compare() { compare_files "$work/$1.xyz" "$work/$2.xyz"; }

# The float operations that can round otherwise on the device, from its float properties
# (`collide devices`: "float: denormals yes, fma yes, correctly rounded divide/sqrt yes").
float_suspects() {
    local suspects=()
    [[ $device_float == *"divide/sqrt no"* ]] &&
        suspects+=("division and sqrt, not correctly rounded on this device (OpenCL allows 2.5 and 3 ulp)")
    [[ $device_float == *"denormals no"* ]] && suspects+=("values below 2^-126, flushed to zero on this device")
    if [[ ${#suspects[@]} -eq 0 ]]; then
        echo "the device has correctly rounded division and sqrt and keeps denormals, so the likely cause is a*b + c contracted into one FMA despite FP_CONTRACT OFF (fma: $([[ $device_float == *"fma yes"* ]] && echo yes || echo no))"
    else
        printf '%s' "${suspects[0]}"
        [[ ${#suspects[@]} -eq 1 ]] || printf '; %s' "${suspects[1]}"
        echo
    fi
}

# Why `opencl` and `cpu` differ on SCENE: two reruns separate the order of the sums from the
# arithmetic of the device.
diagnose() {  # SCENE
    if run_frames cpu-unsorted "$1" cpu --set backend.cpu.skin=0 --set backend.cpu.sort_interval=0 2> /dev/null &&
       [[ $(compare cpu-unsorted opencl) == equal* ]]; then
        echo "the order of the sums: cpu moves the disks into cell order (backend.cpu.sort_interval, default 1) and then adds a disk's contacts in slot order, not in scene order as opencl does; with sort_interval = 0 the bits are equal"
    elif ! run_frames step "$1" step 2> /dev/null || ! run_frames opencl-double "$1" opencl --real double --cl-device "$device" 2> /dev/null; then
        echo "not separated: the double rerun (step against opencl --real double) did not run (no fp64?)"
    elif [[ $(compare step opencl-double) == equal* ]]; then
        echo "the float operations of the device: in double the kernels give step's bits, so the order of the sums and the formulas agree and the float arithmetic rounds otherwise: $(float_suspects)"
    else
        echo "the arithmetic in both precisions: opencl --real double differs from step too, so a*b + c contracted into FMA (applies to float and double alike; the device reports $device_float) or kernels that no longer follow the rules"
    fi
}

# Step 4: cpu against opencl, bit for bit, on each scene of the library. cpu runs its cell path
# (backend.cpu.skin = 0), the search the kernels mirror: its default pair list adds a disk's
# contacts in the list's order, which parts the bits where a disk has three contacts at once.
compare_bits() {
    local path name result equal=0 differ=() left_out=()
    bits_deadline=$(deadline_in "$limit_bits")
    mkdir -p "$out/bits" "$work"
    for name in "${scenes[@]}"; do
        path="$bundle/share/collide/data/scenes/$name.toml"
        [[ -f "$path" ]] || { echo "bits $name: no such scene in the bundle"; left_out+=("$name (no such scene)"); continue; }
        if [[ $(left "$bits_deadline") -le 1 ]]; then left_out+=("$name (out of time)"); status=1; continue; fi
        if ! run_frames cpu "$path" cpu --set backend.cpu.skin=0 2> "$work/error" ||
           ! run_frames opencl "$path" opencl --cl-device "$device" 2> "$work/error"; then
            left_out+=("$name ($(cat "$work/error"))"); echo "bits $name: left out: $(cat "$work/error")"; continue
        fi
        result=$(compare cpu opencl)
        if [[ $result == equal* ]]; then
            equal=$((equal + 1)); echo "bits $name: equal (${result#equal } values)"
        elif [[ $result == "differ frames" ]]; then
            differ+=("$name"); summary "bits $name: the runs differ in their number of frames or disks"
            echo "bits $name: the runs differ in their number of frames or disks"
        else
            read -r _ count values d1 q1 i1 t1 u1 d2 q2 i2 t2 u2 <<< "$result"
            result="differ in $count of $values values; first at t = $t1: $q1 of disk $i1 by $d1 ($u1 float ulps); largest: $q2 of disk $i2 at t = $t2 by $d2 ($u2 float ulps); cause: $(diagnose "$path")"
            differ+=("$name"); echo "bits $name: $result"; summary "bits $name: $result"
        fi
        cp "$work"/cpu.txt "$out/bits/$name-cpu.txt"; cp "$work"/opencl.txt "$out/bits/$name-opencl.txt"
        rm -f "$work"/*.xyz
    done
    summary "bits: equal on $equal of ${#scenes[@]} scenes${differ[*]:+; differ on ${differ[*]}}${left_out[*]:+; left out: ${left_out[*]}}"
}

# Step 5: throughput. The fastest grid mode at each size; the target at N = 4e6 judged on a GPU.
run_bench() {
    local log="$out/bench.log"
    if ! COLLIDE_CL_DEVICE=$device timeout "$limit_bench" "$collide" bench opencl --backend opencl \
            --sizes "${sizes[@]}" --steps "$steps" --max-seconds 30 -o "$out/bench" > "$log" 2>&1; then
        tail -5 "$log"; echo "collide bench opencl failed or ran out of time (bench.log)"; summary "bench: failed (bench.log)"
        status=1; return
    fi
    awk -F, -v target="$target_disk_steps" -v at="$target_size" -v type="$device_type" '
        NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
        $col["part"] == "throughput" && $col["backend"] == "opencl" {
            n = $col["N"]; r = $col["particle_steps_per_s"] + 0
            if (r > best[n]) { best[n] = r; mode[n] = "grid " $col["grid"] ", sort_interval " $col["sort_interval"] }
        }
        END {
            for (n in best) printf "bench N = %d: %.3g disk-steps/s (%s)\n", n, best[n], mode[n] | "sort -t= -k2 -n"
            close("sort -t= -k2 -n")
            for (n in best) if (n + 0 > largest + 0) largest = n
            if (type != "GPU") printf "target: >= %.0e disk-steps/s at N = %d: not judged, measured on a %s device (N = %d: %.3g)\n", target, at, type, largest, best[largest]
            else if (!(at in best)) printf "target: >= %.0e disk-steps/s at N = %d: not measured (sizes without %d)\n", target, at, at
            else printf "target: >= %.0e disk-steps/s at N = %d: %.3g, %s\n", target, at, best[at], (best[at] >= target ? "MET" : "NOT MET")
        }' "$out/bench-opencl.csv" | tee -a "$out/summary.txt"
}

summary() { echo "$*" >> "$out/summary.txt"; }

step() {  # NAME FUNCTION
    local started
    started=$(now)
    echo "== $1"
    "$2"
    echo "-- $1: $(since "$started") s"
    summary "elapsed $1: $(since "$started") s"
}

# ---------------------------------------------------------------------------------------------

script_path=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")
source_dir=$(cd "$(dirname "$script_path")/.." && pwd)
bundle=$(dirname "$script_path") pack_dir="" build="$source_dir/build/release" device=NVIDIA
sizes=(10000 1000000 4000000) steps=100 scenes=() out="" nvidia_library=""
if [[ ${1:-} == --compare ]]; then
    [[ $# -eq 3 && -f $2 && -f $3 ]] || fail "--compare needs two files written by collide export -o NAME.xyz"
    compare_files "$2" "$3"
    exit 0
fi
while [[ $# -gt 0 ]]; do
    [[ $1 == -h || $1 == --help ]] && { usage; exit 0; }
    [[ $# -ge 2 ]] || { usage >&2; fail "option '$1' needs a value"; }
    case "$1" in
        --pack) pack_dir=$2 ;;
        --build) build=$2 ;;
        --bundle) bundle=$2 ;;
        --device) device=$2 ;;
        --nvidia-library) nvidia_library=$2 ;;
        --sizes) IFS=, read -r -a sizes <<< "$2" ;;
        --steps) steps=$2 ;;
        --scenes) IFS=, read -r -a scenes <<< "$2" ;;
        --out) out=$2 ;;
        *) usage >&2; fail "unknown option '$1'" ;;
    esac
    shift 2
done
for n in "${sizes[@]}" "$steps"; do [[ $n =~ ^[1-9][0-9]*$ ]] || fail "--sizes/--steps: '$n' is not a positive whole number"; done

if [[ -n $pack_dir ]]; then pack "$build" "$pack_dir"; exit 0; fi

bundle=$(cd "$bundle" 2> /dev/null && pwd) || fail "--bundle: no folder '$bundle'"
check_bundle
collide="$bundle/bin/collide"
if [[ ${#scenes[@]} -eq 0 ]]; then
    for path in "$bundle"/share/collide/data/scenes/*.toml; do name=${path##*/}; scenes+=("${name%.toml}"); done
fi
out=${out:-gpu-check-results-$(date -u +%Y%m%dT%H%M%SZ)}
[[ ! -e "$out/summary.txt" ]] || fail "--out: '$out' holds the results of an earlier check; name a new folder"
mkdir -p "$out"
out=$(cd "$out" && pwd) results_ready=1
work="$out/work"
# Everything printed, messages included, goes to check.log as well; at the end the copy is
# waited for, so that the last line is not printed after the shell's prompt.
exec > >(tee -a "$out/check.log") 2>&1
copy=$!
finish() {
    rm -rf "$work"
    exec >&- 2>&-
    wait "$copy"
}
trap finish EXIT
started=$(now) status=0
echo "gpu_check: bundle $bundle ($(tr '\n' ' ' < "$bundle/bundle.txt")), results in $out"
summary "bundle: $(tr '\n' ' ' < "$bundle/bundle.txt")"

if [[ ${device,,} == *nvidia* ]]; then find_nvidia_icd; fi
step devices pick_device
step tests run_tests
step bits compare_bits
step bench run_bench
echo "gpu_check: done in $(since "$started") s, status $status; summary: $out/summary.txt"
summary "elapsed total: $(since "$started") s"
exit "$status"
