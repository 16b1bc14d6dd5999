"""Outside solvers through real suites (docs/your-solver.md): the shipped NumPy stepper passes
the checks that apply to a stepped rule, the deliberately wrong one fails the named checks, the
C client matches the NumPy stepper to rounding, a faulty solver fails its cases while the suite
goes on (and what it prints reaches the report escaped), and `collide compare` tells a run
from itself and from one with a solver's restitution edited."""

import html
import json
import os
import pathlib
import subprocess
import sys
import tomllib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "docs" / "examples" / "solvers"
COLLIDE = os.environ.get("COLLIDE_EXE", str(ROOT / "build" / "release" / "collide"))
C_STEPPER = os.environ.get("C_STEPPER", str(ROOT / "build" / "release" / "tests" / "external" / "c_stepper"))


def collide(*args, check=None):
    r = subprocess.run([COLLIDE, *map(str, args)], capture_output=True, text=True, errors="replace")
    if check is not None:
        assert r.returncode == check, r.stdout + r.stderr
    return r


def summary(out):
    return json.loads((out / "summary.json").read_text())


def failed(s, backend):
    return {c["check"] for c in s["checks"] if c["backend"] == backend and c["status"] == "fail"}


def record(out, case):
    text = (out / case["result_file"]).read_text()
    return tomllib.loads(text.split("\n", 1)[1])


def tiny_suite(directory, solver_lines, name="tiny"):
    """One trajectory scene on event and step, plus the [solver] tables given."""
    path = directory / "suite.toml"
    path.write_text(f"""name = "{name}"
scene_dir = "{ROOT / 'data' / 'scenes'}"
reference_dir = "{ROOT / 'data' / 'references'}"
backends = ["event", "step"]
warmup_fraction = 0
time_limit = 60
{solver_lines}
[[scene]]
name = "head_on_equal"
compare = "trajectory"
dt = [2e-3, 1e-3]
seeds = [1, 2]
""")
    return path


@pytest.fixture(scope="module")
def example_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("numpy")
    collide("validate", EXAMPLES / "numpy_stepper.toml", "--out", out, "--jobs", 2,
            "--solver", f"c={C_STEPPER}", "--solver-rule", "c=collide-first")
    return out, summary(out)


def test_the_numpy_stepper_passes_every_check_that_applies(example_run):
    _, s = example_run
    mine = [c for c in s["checks"] if c["backend"] == "numpy"]
    assert len(mine) > 30
    assert failed(s, "numpy") == set(), [c for c in mine if c["status"] == "fail"]
    assert {c["check"] for c in mine if c["status"] == "pass"} >= {"run", "trajectory_error", "energy_drift", "max_overlap"}
    assert failed(s, "c") == set()


def test_the_wrong_stepper_fails_the_checks_that_catch_its_fault(example_run):
    _, s = example_run
    wrong = failed(s, "numpy-wrong")
    # The doubled impulse gains energy at every collision and leaves the exact trajectory; the
    # run itself goes to the end (nothing overflows), so "run" passes.
    assert {"energy_drift", "trajectory_error"} <= wrong
    assert "run" not in wrong
    energy = [c for c in s["checks"] if c["backend"] == "numpy-wrong" and c["check"] == "energy_drift"]
    assert energy and all(c["status"] == "fail" for c in energy)


def test_the_wrong_stepper_work_precision_line_does_not_converge(example_run):
    _, s = example_run
    lines = {(l["scene"], l["backend"]): l for l in s["work_precision"] if l["error_kind"] == "trajectory"} \
        or {(l["scene"], l["backend"]): l for l in s["work_precision"]}
    right, wrong = lines[("head_on_equal", "numpy")], lines[("head_on_equal", "numpy-wrong")]
    assert right["order"] is not None and right["order"] > 0.7, right
    # Its error does not fall with dt: no order, or one far below the rule's first order.
    assert wrong["order"] is None or wrong["order"] < 0.3, wrong


def test_the_c_client_matches_the_numpy_stepper_to_rounding(example_run):
    out, s = example_run
    by_key = {(c["backend"], c["scene"], c["dt"], c["seed"]): c for c in s["cases"]}
    compared = 0
    for (backend, scene, dt, seed), case in by_key.items():
        if backend != "numpy" or case["status"] != "completed":
            continue
        a, b = record(out, case), record(out, by_key[("c", scene, dt, seed)])
        for field in ("x", "y", "vx", "vy"):
            fa, fb = np.array(a["final"][field]), np.array(b["final"][field])
            assert np.allclose(fa, fb, rtol=1e-12, atol=1e-12 * max(1.0, np.abs(fa).max())), (scene, dt, seed, field)
        compared += 1
    assert compared == sum(1 for c in s["cases"] if c["backend"] == "numpy") >= 19


def test_provenance_names_the_command_its_hash_and_version(example_run):
    _, s = example_run
    case = next(c for c in s["cases"] if c["backend"] == "numpy" and c["status"] == "completed")
    p = case["provenance"]
    assert p["solver_version"] == "numpy-stepper 1"
    assert p["solver_python_class"] == "numpy_stepper.py:NumPyStepper"
    import hashlib
    digest = hashlib.sha256((EXAMPLES / "numpy_stepper.py").read_bytes()).hexdigest()
    assert digest in p["solver_files_sha256"]


def test_a_faulty_solver_fails_its_cases_and_the_suite_goes_on(tmp_path):
    suite = tiny_suite(tmp_path, "")
    out = tmp_path / "out"
    r = collide("validate", suite, "--out", out, "--jobs", 2,
                "--solver", "bad=printf '<script>alert(1)</script>\\033[2J'; exit 4")
    assert r.returncode == 1, r.stdout + r.stderr
    s = summary(out)
    bad = [c for c in s["cases"] if c["backend"] == "bad"]
    assert len(bad) == 4 and all(c["status"] == "error" for c in bad)
    d = bad[0]["diagnostic"]
    assert "solver 'bad'" in d and "head_on_equal" in d and "exit status 4" in d and "\\x1b[2J" in d, d
    assert "\x1b" not in d
    assert failed(s, "step") == set() and failed(s, "event") == set()
    # Its run fails, and with it the comparison with event (no trajectory to compare).
    assert failed(s, "bad") == {"run", "trajectory_error"}
    collide("report", out, check=0)
    pages = "".join(p.read_text(errors="replace") for p in (out / "report").glob("*.html"))
    assert "solver 'bad'" in html.unescape(pages)  # shown, as text (the templates escape it)
    assert "<script>alert(1)" not in pages


def test_a_missing_program_and_a_hang_fail_with_their_names(tmp_path):
    suite = tiny_suite(tmp_path, "[solver.gone]\ncommand = \"./no-such-solver\"\n")
    suite.write_text(suite.read_text().replace("time_limit = 60", "time_limit = 2"))
    out = tmp_path / "out"
    collide("validate", suite, "--out", out, "--solver", "stuck=sleep 60; true", check=1)
    s = summary(out)
    gone = next(c for c in s["cases"] if c["backend"] == "gone")
    stuck = next(c for c in s["cases"] if c["backend"] == "stuck")
    assert "solver 'gone'" in gone["diagnostic"] and "exit status 127" in gone["diagnostic"]
    assert "solver 'stuck'" in stuck["diagnostic"] and "still running after the limit" in stuck["diagnostic"]


def test_the_python_api_takes_a_class(tmp_path):
    sys.path.insert(0, str(EXAMPLES))
    import collide as api
    from numpy_stepper import NumPyStepper
    suite = tiny_suite(tmp_path, "")
    s = api.validate(suite, tmp_path / "out", jobs=2, solvers={"mine": NumPyStepper})
    mine = [c for c in s["checks"] if c["backend"] == "mine"]
    assert mine and all(c["status"] != "fail" for c in mine)
    with pytest.raises(ValueError):
        api.validate(suite, tmp_path / "out2", solvers={"mine": 42})


def test_compare_tells_a_run_from_itself_and_from_an_edited_restitution(tmp_path):
    solver = f'[solver.numpy]\npython = "{EXAMPLES / "numpy_stepper.py"}:NumPyStepper"\nrule = "collide-first"\n'
    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir()
    b.mkdir()
    collide("validate", tiny_suite(a, solver), "--out", a / "out", "--jobs", 2, check=0)
    same = collide("compare", a / "out", a / "out", check=0)
    assert "12 bit-identical" in same.stdout and "0 changed status" in same.stdout, same.stdout
    # The same suite with the NumPy stepper's restitution edited to 0.9 in its copy.
    (b / "edited.py").write_text(f"""import sys
sys.path.insert(0, {str(EXAMPLES)!r})
from numpy_stepper import NumPyStepper


class Edited(NumPyStepper):
    def load(self, scene, initial):
        super().load(dict(scene, restitution=0.9), initial)
""")
    edited = solver.replace(f'{EXAMPLES / "numpy_stepper.py"}:NumPyStepper', "edited.py:Edited")
    collide("validate", tiny_suite(b, edited), "--out", b / "out", "--jobs", 2)
    worse = collide("compare", a / "out", b / "out", check=1)
    assert "REGRESSED" in worse.stdout and "numpy" in worse.stdout, worse.stdout
    assert "8 bit-identical" in worse.stdout, worse.stdout   # event and step are untouched
    # The thresholds: tolerating the new failures and any moved observable gives exit status 0.
    collide("compare", a / "out", b / "out", "--allow", 100, "--sigma", 1e300, check=0)
    other = tmp_path / "other"
    other.mkdir()
    collide("validate", tiny_suite(other, "", name="another"), "--out", other / "out", check=0)
    assert collide("compare", a / "out", other / "out").returncode == 2


def test_the_walkthrough_of_your_solver_md_gives_a_report_with_the_solver(tmp_path):
    """docs/your-solver.md's first section, as written: free_flight.py and mine.toml from its
    code blocks (the scene paths pointed at this tree), then validate and report."""
    import re
    text = (ROOT / "docs" / "your-solver.md").read_text()
    blocks = re.findall(r"```(?:python|toml)\n(.*?)```", text, re.S)
    (tmp_path / "free_flight.py").write_text(next(b for b in blocks if b.startswith("# free_flight.py")))
    suite = next(b for b in blocks if b.startswith("# mine.toml"))
    suite = suite.replace("/path/to/collide", str(ROOT)).replace("seeds = [1, 2, 3]", "seeds = [1]")
    (tmp_path / "mine.toml").write_text(suite)
    out = tmp_path / "results"
    collide("validate", tmp_path / "mine.toml", "--out", out, "--jobs", 2, check=1)
    s = summary(out)
    assert "trajectory_error" in failed(s, "free")          # as the page says
    assert failed(s, "event") == set() and failed(s, "step") == set()
    collide("report", out, check=0)
    assert "free" in (out / "report" / "index.html").read_text()


def test_a_refusal_leaves_the_scene_out_with_the_reason(tmp_path):
    """The C client answers "refuse" to an integrate-first scene: the case is left out, as a
    built-in backend's unsupported scene is, and the other scenes still run."""
    path = tiny_suite(tmp_path, "")
    path.write_text(path.read_text() + '\n[[scene]]\nname = "particle_box"\nduration = 0.16666666666666666\noutput_interval = 0.16666666666666666\n')
    out = tmp_path / "out"
    collide("validate", path, "--out", out, "--jobs", 2, "--solver", f"c={C_STEPPER}", check=0)
    s = summary(out)
    box = next(c for c in s["cases"] if c["backend"] == "c" and c["scene"] == "particle_box")
    assert box["status"] == "left_out" and "only the collide-first order" in box["diagnostic"], box
    run = next(c for c in s["checks"] if c["subject"] == box["id"] and c["check"] == "run")
    assert run["status"] == "left_out"
    assert all(c["status"] == "completed" for c in s["cases"] if c["backend"] == "c" and c["scene"] == "head_on_equal")
