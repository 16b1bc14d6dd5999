"""bench/gpu_check.sh and bench/gpu_bundle.sh on the OpenCL device this machine has (PoCL):
the script's path as far as a CPU allows (docs/opencl-backend.md, "On a GPU").

Checked: a carried bundle runs the OpenCL test programs and the bitwise comparison with
`cpu` and prints the throughput target line; a device that is not a GPU is refused without
--allow-cpu; a device that does not exist is refused with its name; a build without
`collide` is refused naming the path."""
import os
import re
import subprocess
import sys
import tempfile

source, build = sys.argv[1], sys.argv[2]
check = os.path.join(source, "bench", "gpu_check.sh")
bundle = os.path.join(source, "bench", "gpu_bundle.sh")
failures = []


def run(*args):
    return subprocess.run(["bash", *args], capture_output=True, text=True, timeout=600)


def expect(condition, what, result=None):
    if not condition:
        failures.append(what + ("" if result is None else "\n--- stdout\n" + result.stdout + "--- stderr\n" + result.stderr))


with tempfile.TemporaryDirectory() as tmp:
    carried = os.path.join(tmp, "carried")
    made = run(bundle, build, carried)
    expect(made.returncode == 0 and os.path.isfile(os.path.join(carried, "collide")), "gpu_bundle.sh made no bundle", made)
    expect(os.path.isfile(os.path.join(carried, "bundle-lib", "libOpenCL.so.1")), "the bundle lacks the OpenCL loader", made)
    expect(not any(n.startswith("libc.so") for n in os.listdir(os.path.join(carried, "bundle-lib"))),
           "the bundle carries the C library", made)

    out = os.path.join(tmp, "out")
    ok = run(check, "--build", carried, "--allow-cpu", "--device", "0", "--sizes", "500 1000", "--steps", "5", "--out", out)
    expect(ok.returncode == 0, "gpu_check.sh --allow-cpu failed on PoCL", ok)
    expect("passed: test_opencl_group" in ok.stdout, "the OpenCL test programs did not run", ok)
    expect("bit for bit" in ok.stdout, "the bitwise comparison with cpu was not reported as equal", ok)
    expect(re.search(r"N = 1000: [0-9.e+]+ disk-steps/s", ok.stdout) is not None, "no throughput line for N = 1000", ok)
    expect(re.search(r"target: >= 1e\+09 disk-steps/s at N = 1000: [0-9.e+]+, (met|NOT met)", ok.stdout) is not None,
           "no target line", ok)
    expect(os.path.isfile(os.path.join(out, "bench-opencl.csv")), "the benchmark's CSV was not kept", ok)

    not_gpu = run(check, "--build", build, "--device", "0", "--out", os.path.join(tmp, "o2"))
    expect(not_gpu.returncode == 2 and "not a GPU" in not_gpu.stderr, "a CPU device was accepted without --allow-cpu", not_gpu)

    missing = run(check, "--build", build, "--allow-cpu", "--device", "NoSuchDevice42", "--out", os.path.join(tmp, "o3"))
    expect(missing.returncode == 2 and "NoSuchDevice42" in missing.stderr, "a missing device was not named", missing)

    empty = os.path.join(tmp, "empty")
    os.makedirs(empty)
    nobuild = run(check, "--build", empty, "--out", os.path.join(tmp, "o4"))
    expect(nobuild.returncode == 2 and empty in nobuild.stderr, "a build without collide was not named", nobuild)

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
