"""Exact outside solvers through the suite exact_solvers.toml (docs/your-solver.md, "An exact
solver"): the shipped exact solver agrees with `event` to rounding and passes every check; each
known-wrong copy of it (faulty_exact.py) acts in the scenes it is claimed to act in, is
measurably off there by the amount its fault implies, and fails the check that names its fault.
"""

import json
import os
import pathlib
import re
import subprocess
import tomllib

import numpy as np
import pytest

HERE = pathlib.Path(__file__).resolve().parent
COLLIDE = os.environ.get("COLLIDE_EXE", str(HERE.parents[1] / "build" / "release" / "collide"))

SCENES = ("head_on_equal", "glancing", "head_on_mass_ratio_10", "newtons_cradle", "chaotic_walled")
# Where each fault acts: every scene has pair collisions from the first time unit on; only the
# walled chaotic scene has a disk reach a wall within its duration.
ACTS_IN = {
    "restitution": set(SCENES),
    "skip": set(SCENES),
    "wall": {"chaotic_walled"},
    "late": set(SCENES),
}
# The checks that name each fault: one of them must fail in every scene where it acts.
NAMED_CHECKS = {
    "restitution": {"energy_drift"},                       # each collision loses 1 - e^2 of its normal energy
    "skip": {"trajectory_error", "energy_drift", "momentum_drift"},  # two disks pass through each other
    "wall": {"wall_penetration", "trajectory_error"},      # a disk leaves the box
    "late": {"trajectory_error"},                          # everything after shifted by 1e-9 x speed
}
# An undeclared outside solver is held to looser limits (energy drift 0.02, trajectory 0.5 r_min):
# a restitution of 0.995 loses 0.4 to 1 % of the energy in the few-body scenes and a 1e-9 delay
# moves the disks by 4e-9 r_min, both inside those. The limits that follow from `exact = true`
# (rounding level, up to the predictability horizon: docs/validation.md) catch them.


def summary(out):
    return json.loads((out / "summary.json").read_text())


def record(out, case):
    return tomllib.loads((out / case["result_file"]).read_text().split("\n", 1)[1])


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    out = tmp_path_factory.mktemp("exact")
    r = subprocess.run([COLLIDE, "validate", HERE / "exact_solvers.toml", "--out", out, "--jobs", "2"],
                       capture_output=True, text=True)
    assert r.returncode in (0, 1), r.stdout + r.stderr       # 1: the faulty solvers fail checks
    s = summary(out)
    assert all(c["status"] == "completed" for c in s["cases"]), [c["diagnostic"] for c in s["cases"] if c["diagnostic"]]
    return out, s


def checks(s, backend, scene=None):
    return [c for c in s["checks"] if c["backend"] == backend and (scene is None or c["scene"] == scene)]


def values(s, backend, scene, check):
    """The measured values of one check of one solver in one scene (one per seed, or one per
    scene for the comparison with event)."""
    return [c["value"] for c in checks(s, backend, scene) if c["check"] == check and c["status"] != "left_out"]


def case(s, backend, scene, seed=1):
    return next(c for c in s["cases"] if (c["backend"], c["scene"], c["seed"]) == (backend, scene, seed))


def test_the_exact_solver_agrees_with_event_to_rounding(run):
    out, s = run
    for scene in ("head_on_equal", "newtons_cradle"):
        mine, event = record(out, case(s, "exact", scene)), record(out, case(s, "event", scene))
        for field in ("x", "y", "vx", "vy"):
            a, b = np.array(mine["final"][field]), np.array(event["final"][field])
            assert np.allclose(a, b, rtol=1e-12, atol=1e-12), (scene, field, a, b)
        assert values(s, "exact", scene, "trajectory_error") == [pytest.approx(0, abs=1e-12)]
    # The same collisions, one for one, in every case (the walled chaotic scene: 34 to 52).
    for c in s["cases"]:
        if c["backend"] == "exact":
            assert c["contacts"] == case(s, "event", c["scene"], c["seed"])["contacts"] > 0, c["id"]


def test_the_exact_solver_agrees_with_event_in_a_periodic_box_and_with_stones(tmp_path):
    """12 disks of the periodic gas in an 8 x 8 periodic box for 5 time units (collisions across
    the box's edges, found through the periodic images), and 20 disks of the gas streaming past
    the column of stones."""
    suite = tmp_path / "periodic.toml"
    suite.write_text(f"""name = "periodic-exact"
scene_dir = "{HERE.parents[1] / 'data' / 'scenes'}"
reference_dir = "{HERE.parents[1] / 'data' / 'references'}"
backends = ["event"]
warmup_fraction = 0
[solver.exact]
python = "{HERE.parents[1] / 'docs' / 'examples' / 'solvers' / 'exact_disks.py'}:ExactDisks"
[[scene]]
name = "periodic_gas"
compare = "trajectory"
duration = 5.0
seeds = [1, 2]
set = {{ "particles.0.count" = [12], "world.box.2" = [8.0], "world.box.3" = [8.0] }}
[[scene]]
name = "stones_and_gas"
compare = "trajectory"
seeds = [1]
set = {{ "particles.1.count" = [20] }}
""")
    out = tmp_path / "out"
    r = subprocess.run([COLLIDE, "validate", suite, "--out", out, "--jobs", "2"], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    s = summary(out)
    assert {c["check"] for c in checks(s, "exact") if c["status"] == "pass"} >= {"momentum_drift", "energy_drift", "trajectory_error"}
    assert [c for c in checks(s, "exact") if c["status"] == "fail"] == []
    assert values(s, "exact", "periodic_gas", "trajectory_error")[0] < 1e-9     # measured: 4.4e-12 r_min
    assert values(s, "exact", "stones_and_gas", "trajectory_error")[0] < 1e-9   # measured: 5.1e-13 r_min
    for c in (c for c in s["cases"] if c["backend"] == "exact"):
        assert c["contacts"] == case(s, "event", c["scene"], c["seed"])["contacts"] >= 10, c["id"]


def test_the_exact_solver_passes_every_check(run):
    _, s = run
    mine = checks(s, "exact")
    assert [c for c in mine if c["status"] == "fail"] == []
    passed = {(c["scene"], c["check"]) for c in mine if c["status"] == "pass"}
    for scene in SCENES:
        assert {(scene, k) for k in ("run", "energy_drift", "max_overlap", "wall_penetration", "trajectory_error")} <= passed


@pytest.mark.parametrize("fault", ACTS_IN)
def test_each_fault_acts_in_the_scenes_it_is_claimed_to(run, fault):
    """A faulty solver says on its log when its fault first changes the run; where it says
    nothing, its run is the exact solver's, bit for bit."""
    out, s = run
    for scene in SCENES:
        for c in (c for c in s["cases"] if c["backend"] == fault and c["scene"] == scene):
            log = (out / "cases" / (c["id"] + ".log")).read_text()
            acted = re.search(r"fault acts: %s: .* at t = (\S+)" % fault, log)
            assert bool(acted) == (scene in ACTS_IN[fault]), (c["id"], log)
            if acted and scene == "chaotic_walled":
                assert float(acted.group(1)) < 1.0, (c["id"], log)      # early: in the first time unit
            if not acted:
                assert record(out, c)["final"] == record(out, case(s, "exact", scene, c["seed"]))["final"], c["id"]


def test_each_fault_is_off_by_what_it_implies(run):
    """The measured values, whatever the limits: each fault moves its own quantity far above what
    the exact solver shows for the same scene (its rounding level)."""
    _, s = run
    for scene in SCENES:
        assert max(values(s, "exact", scene, "energy_drift")) < 1e-13
        assert min(values(s, "restitution", scene, "energy_drift")) > 1e-3
        assert min(values(s, "skip", scene, "trajectory_error")) >= 1.0
        # 1e-9 late at speeds of order 1: displacements of order 1e-9, grown by the scene's chaos,
        # against the exact solver's rounding differences grown by the same chaos.
        late, exact = values(s, "late", scene, "trajectory_error")[0], values(s, "exact", scene, "trajectory_error")[0]
        assert late > 1e-9 and late > 1e3 * exact, (scene, late, exact)
    assert min(values(s, "wall", "chaotic_walled", "wall_penetration")) > 1.0


@pytest.mark.parametrize("fault", [
    "restitution",
    "skip",
    "wall",
    "late",
])
def test_each_faulty_solver_fails_the_check_that_names_its_fault(run, fault):
    _, s = run
    for scene in ACTS_IN[fault]:
        failed = {c["check"] for c in checks(s, fault, scene) if c["status"] == "fail"}
        assert failed & NAMED_CHECKS[fault], (fault, scene, failed)


def test_the_chaotic_suite_passes_event_plain_and_the_exact_solver(tmp_path):
    """validation/suites/chaotic.toml (random sizes, periodic, mass ratio 50; 3 seeds each) with
    the exact NumPy solver declared exact on the command line: two exact solvers that share no
    code with `event` part from it after the predictability horizon, and both pass every check
    (trajectory_error judged up to each run's horizon, which summary.json records)."""
    out = tmp_path / "chaotic"
    exact = HERE.parents[1] / "docs" / "examples" / "solvers" / "exact_disks.py"
    r = subprocess.run([COLLIDE, "validate", HERE.parents[1] / "validation" / "suites" / "chaotic.toml",
                        "--out", out, "--jobs", "2", "--python-solver", f"exact={exact}:ExactDisks",
                        "--solver-exact", "exact"], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    s = summary(out)
    for backend in ("event-plain", "exact"):
        judged = [c for c in checks(s, backend) if c["status"] != "left_out"]
        assert {c["check"] for c in judged} >= {"trajectory_error", "energy_drift"}, backend
        assert [c for c in judged if c["status"] == "fail"] == [], backend
    # Each compared case records its horizon, and it ends before the run does (the scenes are chaotic).
    horizons = [c["trajectory"]["horizon"] for c in s["cases"]
                if c["backend"] == "exact" and c.get("trajectory")]
    assert len(horizons) == 9 and all(0 < h < 20 for h in horizons), horizons
