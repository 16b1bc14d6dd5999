"""`collide explain` on a case of an outside solver (docs/your-solver.md): the replay announces
every time it will stop at, so the solver's program runs once for the whole search, from t = 0 as
the recorded run did, not once per step (a Node engine took two hours for 3000 steps so, paying its
start-up each time, and an engine restarted from a state loses its contact history)."""

import os
import pathlib
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[2]
COLLIDE = os.environ.get("COLLIDE_EXE", str(ROOT / "build" / "release" / "collide"))
C_STEPPER = os.environ.get("C_STEPPER", str(ROOT / "build" / "release" / "tests" / "external" / "c_stepper"))


def collide(*args):
    r = subprocess.run([COLLIDE, *map(str, args)], capture_output=True, text=True, errors="replace")
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def counted_suite(tmp_path):
    """head_on_equal on the C client, whose every program call appends a line to calls.txt."""
    calls = tmp_path / "calls.txt"
    suite = tmp_path / "suite.toml"
    suite.write_text(f"""name = "explain-outside"
scene_dir = "{ROOT / 'data' / 'scenes'}"
backends = ["event"]
reference = "event"
seeds = [1]
warmup_fraction = 0
[solver.c]
command = "echo call >> {calls}; {C_STEPPER}"
rule = "collide-first"
[[scene]]
name = "head_on_equal"
compare = "trajectory"
dt = [1e-3]
""")
    return suite, calls


def test_explain_runs_an_outside_solver_once_for_the_whole_search(tmp_path):
    suite, calls = counted_suite(tmp_path)
    out = tmp_path / "out"
    collide("validate", suite, "--out", out)
    run_calls = calls.read_text().count("call")
    assert run_calls == 1, "the suite's run itself is one call per case"
    text = collide("explain", out, "head_on_equal__c__dt0.001__seed1")
    explain_calls = calls.read_text().count("call") - run_calls
    assert explain_calls == 1, f"explain made {explain_calls} program calls"
    assert "step " in text and "in words" in text, text


def test_a_window_after_the_start_is_still_one_call_and_retraces_the_run(tmp_path):
    suite, calls = counted_suite(tmp_path)
    out = tmp_path / "out"
    collide("validate", suite, "--out", out)
    before = calls.read_text().count("call")
    # --from past an output time: the replay is checked against the record there (it would refuse
    # a path that does not retrace the run), then searched; all in the one call.
    text = collide("explain", out, "head_on_equal__c__dt0.001__seed1", "--from", "0.35", "--to", "1.5")
    assert calls.read_text().count("call") - before == 1
    assert "step " in text, text
