# collide.validate: a suite run from Python writes what `collide validate` writes and returns
# summary.json as a dict. It runs in a child interpreter: the suite runner forks one process per
# case, and a fork is safest from a process that has not started other threads (OpenMP's pool,
# which the cpu backend's tests in this process start).
import json
import os
import subprocess
import sys

SUITE = """name = "python_tiny"
description = "Two backends on one two-disk scene: the Python validate test"
scene_dir = "{scenes}"
backends = ["event", "step"]
reference = "event"
seeds = [1]
time_limit = 60

[[scene]]
name = "head_on_equal"
compare = "trajectory"
dt = [1e-3]
"""

SCRIPT = """
import json, sys, collide
summary = collide.validate(sys.argv[1], sys.argv[2])
print("SUMMARY " + json.dumps({"keys": sorted(summary), "cases": len(summary["cases"]),
                               "checks": [c["status"] for c in summary["checks"]]}))
"""


def test_validate_returns_the_summary(tmp_path, root):
    suite = tmp_path / "tiny.toml"
    suite.write_text(SUITE.format(scenes=root / "data" / "scenes"))
    out = tmp_path / "results"
    run = subprocess.run([sys.executable, "-c", SCRIPT, str(suite), str(out)], capture_output=True, text=True,
                         timeout=300, env=dict(os.environ))
    assert run.returncode == 0, run.stderr
    line = [x for x in run.stdout.splitlines() if x.startswith("SUMMARY ")][0]
    got = json.loads(line[len("SUMMARY "):])
    assert "cases" in got["keys"] and "checks" in got["keys"]
    assert got["cases"] == 2 and got["checks"] and "fail" not in got["checks"]
    assert "checks    " in run.stdout and "output    " in run.stdout  # the CLI's summary lines
    assert (out / "summary.json").exists() and (out / "junit.xml").exists()
