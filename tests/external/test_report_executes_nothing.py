"""ReportExecutesNothing (docs/refusals.md, "What collide never does"): `collide report DIR` on a
results directory someone sent, which carries its own suite file and an outside solver that
would leave a marker file each time it runs, runs no program of theirs. The energy jumps the
report explains were explained by `collide validate`, which runs the solvers anyway, and are
read from summary.json; the report creates no marker and no solver request directory.
"""

import json
import os
import pathlib
import shutil
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "docs" / "examples" / "solvers"
COLLIDE = os.environ.get("COLLIDE_EXE", str(ROOT / "build" / "release" / "collide"))

# An outside solver (the deliberately wrong stepper: its energy jumps at the collision) that
# leaves a file named `ran` beside itself whenever it is loaded, that is at every solver call.
MARKED_SOLVER = '''import pathlib

from numpy_wrong import ImpulseTwice

pathlib.Path(__file__).with_name("ran").touch()


class Marked(ImpulseTwice):
    pass
'''

SUITE = f'''name = "sent"
scene_dir = "{ROOT / 'data' / 'scenes'}"
reference_dir = "{ROOT / 'data' / 'references'}"
backends = ["event"]
warmup_fraction = 0
time_limit = 60

[solver.marked]
python = "marked_solver.py:Marked"
rule = "collide-first"

[[scene]]
name = "head_on_equal"
compare = "trajectory"
dt = [2e-3]
seeds = [1]
'''


def collide(*args, env=None):
    return subprocess.run([COLLIDE, *map(str, args)], capture_output=True, text=True, errors="replace",
                          env={**os.environ, **(env or {})})


def test_report_executes_nothing(tmp_path):
    sent = tmp_path / "sent"  # what someone sent: their suite, their solver, their results
    sent.mkdir()
    for name in ("numpy_stepper.py", "numpy_wrong.py"):
        shutil.copy(EXAMPLES / name, sent / name)
    (sent / "marked_solver.py").write_text(MARKED_SOLVER)
    (sent / "suite.toml").write_text(SUITE)
    out, marker = sent / "results", sent / "ran"
    r = collide("validate", sent / "suite.toml", "--out", out, "--jobs", 2)
    assert r.returncode in (0, 1), r.stdout + r.stderr
    assert marker.exists(), "the marked solver did not run under validate: the test proves nothing"

    marker.unlink()
    requests = tmp_path / "tmp"  # where an outside solver's request directories are made
    requests.mkdir()
    r = collide("report", out, env={"TMPDIR": str(requests)})
    assert not marker.exists(), "collide report ran the solver named in the results directory"
    assert not list(requests.iterdir()), f"collide report made solver requests: {list(requests.iterdir())}"
    assert r.returncode == 0, r.stdout + r.stderr
    # What it lays out instead: the explanation validate stored with the results.
    summary = json.loads((out / "summary.json").read_text())
    jumps = [j for j in summary["energy_jumps"] if j["backend"] == "marked"]
    assert jumps and jumps[0]["explained"], summary["energy_jumps"]
    page = (out / "report" / "index.html").read_text()
    assert "marked" in page and "In detail:" in page
