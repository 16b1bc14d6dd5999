"""bench/gpu_check.sh as far as a CPU allows: its PoCL path (docs/opencl-backend.md, "Checking
on a GPU").

    test_gpu_check.py SOURCE BUILD run       a bundle packed from BUILD runs the whole check on
                                             PoCL with small sizes, and its summary says what
                                             each step found; the comparison of step 4
                                             finds one velocity one float ulp apart
    test_gpu_check.py SOURCE BUILD refusals  asked for the GPU where no NVIDIA ICD is
                                             registered (OCL_ICD_VENDORS an empty folder), the
                                             check stops at once and names what is missing;
                                             a library named by --nvidia-library is
                                             registered for the run; a missing device and a
                                             folder without a bundle are named too

Both pack their own bundle into a temporary folder, as a person does on the build machine."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy

source, build, mode = sys.argv[1], sys.argv[2], sys.argv[3]
script = os.path.join(source, "bench", "gpu_check.sh")
pocl = "Portable Computing Language"  # the CPU device of CI and of this machine
scenes = ["head_on_equal", "glancing", "particle_box"]
failures = []


def run(*args, env=None):
    result = subprocess.run(["bash", *args], capture_output=True, text=True, timeout=300,
                            env=dict(os.environ, **(env or {})))
    result.text = result.stdout + result.stderr
    return result


def expect(condition, what, shown=""):
    if not condition:
        failures.append(what + ("\n--- output\n" + shown if shown else ""))


def pack(tmp):
    bundle = os.path.join(tmp, "bundle")
    made = run(script, "--pack", bundle, "--build", build)
    expect(made.returncode == 0, "--pack failed", made.text)
    lib = os.path.join(bundle, "lib")
    carried = os.listdir(lib) if os.path.isdir(lib) else []
    expect("libOpenCL.so.1" in carried, "the bundle lacks the ICD loader libOpenCL.so.1", made.text)
    expect(not any(re.match(r"(libc|libm|ld-linux[^.]*)\.so", n) for n in carried),
           "the bundle carries the C library or the loader: " + " ".join(sorted(carried)))
    expect(not any("pocl" in n.lower() for n in carried), "the bundle carries a vendor's ICD (PoCL)")
    for path in ["bin/collide", "gpu_check.sh", "bundle.txt", "share/collide/data/scenes/particle_box.toml"]:
        expect(os.path.isfile(os.path.join(bundle, path)), "the bundle lacks " + path, made.text)
    tests = os.listdir(os.path.join(bundle, "tests")) if os.path.isdir(os.path.join(bundle, "tests")) else []
    expect(len(tests) >= 6 and all(t.startswith("test_opencl_") for t in tests),
           "the bundle's OpenCL test programs: " + " ".join(tests))
    return bundle, len(tests)


def summary_of(out):
    path = os.path.join(out, "summary.txt")
    return open(path).read() if os.path.isfile(path) else ""


def check_run(tmp):
    bundle, programs = pack(tmp)
    out = os.path.join(tmp, "results")
    checked = run(os.path.join(bundle, "gpu_check.sh"), "--device", pocl, "--sizes", "1000,4000", "--steps", "10",
                  "--scenes", ",".join(scenes), "--out", out)
    expect(checked.returncode == 0, "the check failed on PoCL (status %d)" % checked.returncode, checked.text)
    summary = summary_of(out)
    shown = summary + "\n--- check output\n" + checked.text
    expect(re.search(r"^device: \[\d+\] .*\(CPU, .*; float: denormals (yes|no), fma (yes|no), "
                     r"correctly rounded divide/sqrt (yes|no)$", summary, re.M) is not None,
           "no device line with its float properties", shown)
    expect(f"tests: {programs} passed, 0 failed" in summary, f"not all {programs} OpenCL test programs passed", shown)

    # Bits: every scene equal, or each differing one named with its first and largest
    # difference and a cause.
    bits = re.search(r"^bits: equal on (\d+) of (\d+) scenes(; differ on (.*))?$", summary, re.M)
    expect(bits is not None and int(bits.group(2)) == len(scenes), "no bits line for all scenes", shown)
    if bits:
        differing = bits.group(4).split() if bits.group(4) else []
        expect(int(bits.group(1)) + len(differing) == len(scenes), "scenes neither equal nor named as differing", shown)
        for name in differing:
            line = re.search(rf"^bits {name}: differ in \d+ of \d+ values; first at t = \S+: (x|y|vx|vy) of disk \d+ "
                             rf"by [0-9.e+-]+ .*; largest: .*; cause: (.+)$", summary, re.M)
            expect(line is not None and len(line.group(2)) > 20, f"scene {name} differs without its differences and cause",
                   shown)

    for n in (1000, 4000):
        rate = re.search(rf"^bench N = {n}: ([0-9.e+]+) disk-steps/s \(grid \w+", summary, re.M)
        expect(rate is not None and float(rate.group(1)) > 0, f"no disk-steps per second at N = {n}", shown)
    expect(re.search(r"^target: >= 1e\+09 disk-steps/s at N = 4000000: not judged, measured on a CPU device "
                     r"\(N = 4000: [0-9.e+]+\)$", summary, re.M) is not None, "the target line on a CPU", shown)
    for step in ("devices", "tests", "bits", "bench", "total"):
        expect(re.search(rf"^elapsed {step}: [0-9.]+ s$", summary, re.M) is not None, f"no elapsed time of {step}", shown)
    for kept in ("check.log", "devices.txt", "bench-opencl.csv", "bench-opencl.json", "tests/test_opencl_group.log"):
        expect(os.path.isfile(os.path.join(out, kept)), "the results lack " + kept, shown)
    expect(not os.path.exists(os.path.join(out, "work")), "the scratch folder was left in the results")
    check_comparison(tmp, bundle)
    check_deadlines_at_any_hour(tmp, bundle, programs)


def check_deadlines_at_any_hour(tmp, bundle, programs):
    """The steps' deadlines are epoch times: at a clock reading that 6 significant digits would
    round down by more than a step's limit (awk's plain print), every test program must still get
    its full time. The clock is frozen there by a `date` found first on PATH."""
    shim = os.path.join(tmp, "frozen-clock")
    os.makedirs(shim)
    real_date = shutil.which("date")
    with open(os.path.join(shim, "date"), "w") as f:
        f.write('#!/bin/bash\nif [[ "$1" == "+%s.%N" ]]; then echo 1795864303.500000000; '
                f'else exec {real_date} "$@"; fi\n')
    os.chmod(os.path.join(shim, "date"), 0o755)
    out = os.path.join(tmp, "results-frozen-clock")
    checked = run(os.path.join(bundle, "gpu_check.sh"), "--device", pocl, "--sizes", "1000", "--steps", "10",
                  "--scenes", "head_on_equal", "--out", out, env={"PATH": shim + os.pathsep + os.environ["PATH"]})
    summary = summary_of(out)
    expect(f"tests: {programs} passed, 0 failed" in summary,
           "with the clock at 1795864303.5 s the test programs did not get their time (a deadline rounded?)",
           summary + "\n--- check output\n" + checked.text)


def check_comparison(tmp, bundle):
    """Step 4's comparison on a run and a copy of it with one velocity moved by one float ulp."""
    env = {"LD_LIBRARY_PATH": os.path.join(bundle, "lib")}
    collide = os.path.join(bundle, "bin", "collide")
    scene = os.path.join(bundle, "share", "collide", "data", "scenes", "head_on_equal.toml")
    run_file, frames = os.path.join(tmp, "run.h5"), os.path.join(tmp, "a.xyz")
    for command in ([collide, "run", scene, "--backend", "cpu", "--frames", "-o", run_file],
                    [collide, "export", run_file, "-o", frames]):
        made = subprocess.run(command, capture_output=True, text=True, env=dict(os.environ, **env))
        expect(made.returncode == 0, " ".join(command) + " failed", made.stdout + made.stderr)
    lines = open(frames).read().splitlines()
    # Frame 3 (count line, header, 2 disks each), disk 1: vx (field 7) one float spacing further from 0.
    k = 3 * 4 + 2 + 1
    fields = lines[k].split()
    vx = numpy.float32(float(fields[6]))
    moved = numpy.nextafter(vx, numpy.float32(numpy.copysign(numpy.inf, vx)), dtype=numpy.float32)  # away from 0: one spacing of its binade
    fields[6] = repr(float(moved))
    time = re.search(r"Time=(\S+)", lines[k - 2]).group(1)
    changed = os.path.join(tmp, "b.xyz")
    open(changed, "w").write("\n".join(lines[:k] + [" ".join(fields)] + lines[k + 1:]) + "\n")

    same = run(script, "--compare", frames, frames)
    expect(same.stdout.split()[:1] == ["equal"], "a run compared with itself is not equal", same.text)
    differ = run(script, "--compare", frames, changed).stdout.split()
    values = 4 * 2 * (len(lines) // 4)
    expected = ["differ", "1", str(values), "%.3g" % abs(float(moved) - float(vx)), "vx", "1", time, "1"]
    expect(differ[:8] == expected and differ[3:8] == differ[8:13],
           "one velocity one ulp apart: expected %s, got %s" % (expected, differ))


def pocl_library_path():
    listed = subprocess.run(["/sbin/ldconfig", "-p"], capture_output=True, text=True).stdout
    found = re.search(r"^\s*libpocl\.so\S* \(.*x86-64.*\) => (\S+)$", listed, re.M)
    expect(found is not None, "PoCL's library is not in ldconfig -p (install pocl-opencl-icd)", listed)
    return found.group(1) if found else "/nonexistent/libpocl.so"


def check_refusals(tmp):
    bundle, _ = pack(tmp)
    empty = os.path.join(tmp, "no-vendors")
    os.makedirs(empty)
    out = os.path.join(tmp, "no-icd")
    refused = run(os.path.join(bundle, "gpu_check.sh"), "--out", out, env={"OCL_ICD_VENDORS": empty})
    expect(refused.returncode == 2, "asked for the GPU without an NVIDIA ICD, the check did not stop with status 2",
           refused.text)
    expect("no NVIDIA OpenCL ICD" in refused.text and empty in refused.text,
           "the refusal does not name the missing NVIDIA ICD and the vendors folder", refused.text)
    expect("== tests" not in refused.text, "the check went on without a device", refused.text)
    expect("failed: no NVIDIA OpenCL ICD" in summary_of(out), "the refusal is not in the summary", refused.text)

    # The registration of a driver without its ICD file, with PoCL's library standing in for
    # NVIDIA's: the only vendor the loader then sees is the one the check registered.
    pocl_library = pocl_library_path()
    out = os.path.join(tmp, "registered")
    registered = run(os.path.join(bundle, "gpu_check.sh"), "--nvidia-library", pocl_library, "--out", out,
                     env={"OCL_ICD_VENDORS": empty})
    icd = os.path.join(out, "vendors", "nvidia.icd")
    expect(os.path.isfile(icd) and open(icd).read().strip() == pocl_library and "registered for this run" in registered.text,
           "--nvidia-library was not registered in the results' vendors folder", registered.text)
    devices = os.path.join(out, "devices.txt")
    expect(os.path.isfile(devices) and pocl in open(devices).read(), "the registered library's device is not listed",
           registered.text)
    expect(registered.returncode == 2 and "no OpenCL device matches --device 'NVIDIA'" in registered.text,
           "a CPU device was taken for the NVIDIA GPU", registered.text)

    missing = run(os.path.join(bundle, "gpu_check.sh"), "--device", "NoSuchDevice42", "--out", os.path.join(tmp, "o2"))
    expect(missing.returncode == 2 and "NoSuchDevice42" in missing.text, "a missing device was not named", missing.text)

    nothing = os.path.join(tmp, "not-a-bundle")
    os.makedirs(nothing)
    refused = run(script, "--bundle", nothing, "--out", os.path.join(tmp, "o3"))
    expect(refused.returncode == 2 and nothing in refused.text and "--pack" in refused.text,
           "a folder without a bundle was not named", refused.text)


with tempfile.TemporaryDirectory() as tmp:
    {"run": check_run, "refusals": check_refusals}[mode](tmp)

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
