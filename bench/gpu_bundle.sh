#!/usr/bin/env bash
# Packs what bench/gpu_check.sh needs from a release build into one folder that can be carried
# to a GPU machine without a package registry: the `collide` program, the OpenCL test programs,
# and every shared library they load that is not part of the C library itself (HDF5, GSL, the
# OpenCL ICD loader, ...), in DIR/bundle-lib. The driver's own OpenCL library stays the GPU
# machine's. Then, there: bench/gpu_check.sh --build DIR.
set -euo pipefail

build=${1:-build/release}
dir=${2:-gpu-bundle}
[[ -x "$build/collide" ]] || { echo "gpu_bundle: no program '$build/collide': build it first (cmake --build $build)" >&2; exit 2; }
mkdir -p "$dir/tests/opencl" "$dir/bundle-lib"
cp "$build/collide" "$dir/"
for t in "$build"/tests/opencl/test_opencl_*; do [[ -f "$t" && -x "$t" ]] && cp "$t" "$dir/tests/opencl/"; done

# The C library, the dynamic loader and the C++ runtime's own core are the GPU machine's: a
# carried copy of them would not match its loader.
keep_out='^(libc|libm|libdl|libpthread|librt|ld-linux[^ ]*|libresolv|libutil)\.so'
for program in "$dir/collide" "$dir"/tests/opencl/*; do
    ldd "$program" | awk '/=> \// { print $1, $3 }' | while read -r name path; do
        grep -Eq "$keep_out" <<< "$name" || cp -L -n "$path" "$dir/bundle-lib/$name"
    done
done
du -sh "$dir" | awk '{ print "gpu_bundle: " $2 " holds " $1 "; run bench/gpu_check.sh --build " $2 " on the GPU machine" }'
