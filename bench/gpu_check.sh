#!/usr/bin/env bash
# The GPU check: the `opencl` backend on a machine with an NVIDIA GPU, in one short run.
#
# Such a machine often has no package registry, so this script installs nothing and builds
# nothing: it runs a release build made beforehand on a Debian 12 machine and carried over
# with the shared libraries it needs (bench/gpu_bundle.sh makes that folder). It
#   1. finds the device (the NVIDIA OpenCL ICD registered in /etc/OpenCL/vendors, or the
#      driver's libnvidia-opencl.so.1 registered for this run alone where the file is missing);
#   2. runs the OpenCL test programs on it; among them OpenclGroup.GroupLaunchesEqualCpuBitwise holds
#      `opencl` (float) on the device to the same bits as `cpu` on the host;
#   3. runs `collide bench opencl` at N = 1e4, 1e6 and 4e6 and prints the particle-steps per
#      second of the fastest grid mode against the target, >= 1e9 at N = 4e6.
# docs/opencl-backend.md, "On a GPU", records what it gave. It finishes in under 6 minutes on
# an H100; --allow-cpu runs the same steps on any OpenCL device (PoCL), which is how the test
# run checks the script itself.
set -euo pipefail

usage() {
    cat <<'EOF'
usage: bench/gpu_check.sh [--build DIR] [--device TEXT] [--allow-cpu] [--sizes "N ..."]
                          [--steps N] [--out DIR]
  --build DIR     release build to run (default build/release; DIR/bundle-lib is put on the
                  library path when present)
  --device TEXT   OpenCL device: index or name substring (default NVIDIA)
  --allow-cpu     accept a device that is not a GPU (checks the script on PoCL)
  --sizes "N ..." disk counts of the throughput part (default "10000 1000000 4000000")
  --steps N       timed steps per throughput case (default 100)
  --out DIR       where logs and the benchmark's CSV/JSON go (default gpu-check)
EOF
}

fail() { echo "gpu_check: $*" >&2; exit 2; }

build=build/release device=NVIDIA allow_cpu=0 sizes="10000 1000000 4000000" steps=100 out=gpu-check
while [[ $# -gt 0 ]]; do
    case "$1" in
        --build) build="$2"; shift 2 ;;
        --device) device="$2"; shift 2 ;;
        --allow-cpu) allow_cpu=1; shift ;;
        --sizes) sizes="$2"; shift 2 ;;
        --steps) steps="$2"; shift 2 ;;
        --out) out="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) usage >&2; fail "unknown argument '$1'" ;;
    esac
done

collide="$build/collide"
[[ -x "$collide" ]] || fail "no program '$collide': make a release build first (cmake --preset release && cmake --build build/release) and carry it here (bench/gpu_bundle.sh)"
[[ -d "$build/bundle-lib" ]] && export LD_LIBRARY_PATH="$build/bundle-lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
mkdir -p "$out"
out=$(cd "$out" && pwd)

# 1. The NVIDIA ICD. A driver installed without its ICD file leaves the loader blind to it:
# register the library for this run in a folder of our own (OCL_ICD_VENDORS), never in /etc.
register_nvidia_icd() {
    ls /etc/OpenCL/vendors/*nvidia*.icd > /dev/null 2>&1 && return 0
    local lib
    for lib in /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1 /usr/lib64/libnvidia-opencl.so.1 \
               /usr/local/nvidia/lib64/libnvidia-opencl.so.1 /usr/lib/libnvidia-opencl.so.1; do
        if [[ -e "$lib" ]]; then
            mkdir -p "$out/vendors"
            echo "$lib" > "$out/vendors/nvidia.icd"
            ls /etc/OpenCL/vendors/*.icd > /dev/null 2>&1 && cp /etc/OpenCL/vendors/*.icd "$out/vendors/" 2>/dev/null || true
            export OCL_ICD_VENDORS="$out/vendors"
            echo "gpu_check: registered $lib for this run (OCL_ICD_VENDORS=$OCL_ICD_VENDORS)"
            return 0
        fi
    done
    return 1
}
register_nvidia_icd || [[ $allow_cpu == 1 ]] || echo "gpu_check: no NVIDIA OpenCL ICD file or libnvidia-opencl.so.1 found"

"$collide" devices > "$out/devices.txt" 2>&1 || { cat "$out/devices.txt" >&2; fail "no OpenCL platform: see the list above"; }
picked=$(grep -i -F -- "$device" "$out/devices.txt" | grep -E '^\s*\[[0-9]+\]' | head -1 || true)
[[ -n "$picked" ]] || { cat "$out/devices.txt" >&2; fail "no OpenCL device matches '$device'"; }
if [[ $allow_cpu == 0 ]] && ! grep -q "GPU" <<< "$picked"; then
    cat "$out/devices.txt" >&2
    fail "the device matching '$device' is not a GPU (pass --allow-cpu to check the script on it)"
fi
echo "device: $(sed 's/^\s*//' <<< "$picked")"
export COLLIDE_CL_DEVICE="$device"

# 2. The OpenCL tests on the device, run from their binaries (a carried build tree's CTest
# files name the paths of the machine that built it); among them the bitwise comparison with
# `cpu`.
echo "== OpenCL tests on the device (log: $out/tests.log)"
: > "$out/tests.log"
tests_ok=1 ran=0
for test in "$build"/tests/opencl/test_opencl_*; do
    [[ -f "$test" && -x "$test" ]] || continue
    ran=$((ran + 1))
    if "$test" --gtest_brief=1 >> "$out/tests.log" 2>&1; then echo "passed: ${test##*/}"
    else echo "FAILED: ${test##*/}"; tests_ok=0; fi
done
[[ $ran -gt 0 ]] || fail "no OpenCL test programs in $build/tests/opencl: build them (cmake --build $build)"
if "$build/tests/opencl/test_opencl_group" --gtest_filter='*EqualCpuBitwise*' > "$out/bits.log" 2>&1; then
    echo "bits: opencl (float) on the device equals cpu on the host, bit for bit"
else
    echo "bits: opencl on the device DIFFERS from cpu ($out/bits.log names the first differing disk);" \
         "the kernels turn off contraction into FMA (#pragma OPENCL FP_CONTRACT OFF) and ask for" \
         "correctly rounded float division and sqrt (-cl-fp32-correctly-rounded-divide-sqrt)," \
         "so look next at denormals flushed to zero and at the device's sqrt/division rounding"
fi

# 3. Throughput at the sizes of the target.
echo "== collide bench opencl --sizes $sizes (log: $out/bench.log)"
# shellcheck disable=SC2086
"$collide" bench opencl --backend opencl --sizes $sizes --steps "$steps" --max-seconds 120 \
    --out "$out/bench" > "$out/bench.log" 2>&1 || { tail -20 "$out/bench.log" >&2; fail "collide bench opencl failed"; }

# The fastest grid mode at each size, against the target at the largest.
awk -F, -v target=1e9 -v largest="$(tr ' ' '\n' <<< "$sizes" | sort -n | tail -1)" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    $col["part"] == "throughput" && $col["backend"] == "opencl" {
        n = $col["N"]; r = $col["particle_steps_per_s"] + 0
        if (r > best[n]) { best[n] = r; mode[n] = $col["grid"] " sort_interval " $col["sort_interval"] }
    }
    END {
        for (n in best) printf "N = %d: %.3g disk-steps/s (%s)\n", n, best[n], mode[n]
        if (largest in best) {
            verdict = best[largest] >= target ? "met" : "NOT met"
            printf "target: >= %.0e disk-steps/s at N = %d: %.3g, %s\n", target, largest, best[largest], verdict
        } else print "target: no measurement at N = " largest
    }' "$out/bench-opencl.csv" | LC_ALL=C sort -k1,1 -k3,3n

[[ $tests_ok == 1 ]] || fail "OpenCL tests failed on the device: see $out/tests.log"
