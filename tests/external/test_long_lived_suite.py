"""A long-lived outside solver through `collide validate` (docs/your-solver.md, "A solver that
serves many calls"): one worker starts it once for many cases; a crash in the middle fails that
case alone, the next case starts it again and passes; a hang is killed at the call's limit; when
collide exits, the copy still running has read end of file and exited, and no copy is left."""
import json
import os
import pathlib
import subprocess
import time

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
COLLIDE = os.environ.get("COLLIDE_EXE", str(ROOT / "build" / "release" / "collide"))
SOLVER = ROOT / "tests" / "external" / "long_lived_solver.py"


def run_suite(tmp_path, seeds, long_lived=True, time_limit=6):
    log = tmp_path / "starts.txt"
    suite = tmp_path / "suite.toml"
    suite.write_text(f"""name = "long-lived"
scene_dir = "{ROOT / 'data' / 'scenes'}"
backends = ["event"]
reference = "event"
seeds = {seeds}
warmup_fraction = 0
time_limit = {time_limit}
[output]
hdf5 = false
[solver.served]
command = "/usr/bin/python3 {SOLVER} {log}"
long_lived = {str(long_lived).lower()}
[[scene]]
name = "head_on_equal"
dt = [2e-3]
""")
    out = tmp_path / "out"
    start = time.monotonic()
    r = subprocess.run([COLLIDE, "validate", str(suite), "--out", str(out), "--jobs", "1"], capture_output=True, text=True)
    elapsed = time.monotonic() - start
    summary = json.loads((out / "summary.json").read_text())
    cases = {c["seed"]: c for c in summary["cases"] if c["backend"] == "served"}
    lines = log.read_text().split() if log.exists() else []
    starts = [int(p) for w, p in zip(lines[::2], lines[1::2]) if w == "start"]
    exits = [int(p) for w, p in zip(lines[::2], lines[1::2]) if w == "exit"]
    return cases, starts, exits, elapsed, r


def gone(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    return False


def test_one_start_serves_every_case_of_a_worker_and_ends_with_collide(tmp_path):
    cases, starts, exits, _, run = run_suite(tmp_path, [1, 2, 4, 6])
    assert sorted(cases) == [1, 2, 4, 6], run.stderr[-2000:]
    assert all(c["status"] == "completed" for c in cases.values()), cases
    assert len(starts) == 1, starts          # one worker (--jobs 1): one start for four cases
    assert exits == starts                   # it read end of file when the worker ended
    assert all(gone(pid) for pid in starts)  # and was reaped


def test_a_crash_fails_one_case_and_a_hang_is_killed_at_the_limit(tmp_path):
    cases, starts, exits, elapsed, run = run_suite(tmp_path, [1, 2, 3, 4, 5, 6])
    status = {seed: c["status"] for seed, c in cases.items()}
    assert status == {1: "completed", 2: "completed", 3: "error", 4: "completed", 5: "error", 6: "completed"}, \
        (status, run.stderr[-2000:])
    crash, hang = json.dumps(cases[3]), json.dumps(cases[5])
    # (the shell that runs the command reports its child's signal 11 as exit status 139)
    assert "solver 'served'" in crash and "its server ended before answering: exit status 139" in crash, crash
    assert "request seed 3" in crash and "request seed 2" not in crash  # its output of this case alone
    assert "solver 'served'" in hang and "still running after the limit of 2.7 s" in hang, hang
    assert len(starts) == 3, starts          # the first, after the crash, after the hang
    assert exits == starts[-1:]              # the last copy read end of file; the others were ended
    assert all(gone(pid) for pid in starts)
    assert elapsed < 60, elapsed


def suite_without_the_solver(tmp_path, name):
    """A suite of three cases that names no outside solver: the caller gives it one."""
    suite = tmp_path / "suite.toml"
    suite.write_text(f"""name = "{name}"
scene_dir = "{ROOT / 'data' / 'scenes'}"
backends = ["event"]
reference = "event"
seeds = [1, 2, 4]
warmup_fraction = 0
[output]
hdf5 = false
[[scene]]
name = "head_on_equal"
dt = [2e-3]
""")
    return suite


def test_the_command_line_declares_it_too(tmp_path):
    log = tmp_path / "starts.txt"
    suite = suite_without_the_solver(tmp_path, "long-lived-cli")
    command = ["--solver", f"served=/usr/bin/python3 {SOLVER} {log}", "--jobs", "1"]
    r = subprocess.run([COLLIDE, "validate", str(suite), "--out", str(tmp_path / "out"), *command,
                        "--solver-long-lived", "served"], capture_output=True, text=True)
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert [c["status"] for c in summary["cases"] if c["backend"] == "served"] == ["completed"] * 3, r.stderr[-2000:]
    assert log.read_text().split()[::2] == ["start", "exit"]
    wrong = subprocess.run([COLLIDE, "validate", str(suite), "--out", str(tmp_path / "out2"), *command,
                            "--solver-long-lived", "servd"], capture_output=True, text=True)
    assert wrong.returncode != 0 and "--solver-long-lived servd: no --solver or --python-solver named 'servd'" in wrong.stderr


def test_the_python_api_declares_it_too(tmp_path):
    import collide  # the module built beside the program (PYTHONPATH)
    log = tmp_path / "starts.txt"
    suite = suite_without_the_solver(tmp_path, "long-lived-python")
    served = {"command": f"/usr/bin/python3 {SOLVER} {log}", "long_lived": True}
    summary = collide.validate(suite, tmp_path / "out", jobs=1, solvers={"served": served})
    assert [c["status"] for c in summary["cases"] if c["backend"] == "served"] == ["completed"] * 3
    words = log.read_text().split()[::2] if log.exists() else []  # a one-shot call writes nothing there
    assert words == ["start", "exit"]  # one worker: one start for three cases
    # A key it does not know is refused, not ignored; a class cannot be long-lived.
    with pytest.raises(ValueError, match="solvers\\['served'\\]: no such key 'long-lived'"):
        collide.validate(suite, tmp_path / "out2", solvers={"served": {**served, "long-lived": True}})
    with pytest.raises(ValueError, match="long_lived: expected a program"):
        collide.validate(suite, tmp_path / "out3", solvers={"served": {"python": f"{SOLVER}:C", "long_lived": True}})
