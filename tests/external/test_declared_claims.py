"""An outside solver declared exact is held to rounding (docs/validation.md, "What a solver
claims"): through `collide validate --python-solver`, the class's own `exact = True` is read
and a restitution of 0.995 fails energy_drift on head_on_equal, where the honest copy and
event-plain pass every check; the same lossy class declaring nothing passes the loose limit."""
import json
import os
import pathlib
import subprocess

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = HERE.parents[1]
COLLIDE = os.environ.get("COLLIDE_EXE", str(SOURCE / "build" / "release" / "collide"))
SOLVERS = HERE / "test_declared_claims_solver.py"

SUITE = """name = "declared"
scene_dir = "%s/data/scenes"
backends = ["event", "event-plain"]
seeds = [1]
[[scene]]
name = "head_on_equal"
compare = "trajectory"
dt = [1e-3]
""" % SOURCE


def validate(out, *solver_options):
    suite = out.with_suffix(".toml")
    suite.write_text(SUITE)
    run = subprocess.run([COLLIDE, "validate", str(suite), "--out", str(out), "--jobs", "2", *solver_options],
                         capture_output=True, text=True)
    assert (out / "summary.json").exists(), run.stderr
    summary = json.loads((out / "summary.json").read_text())
    return {(c["backend"], c["check"]): c for c in summary["checks"]}, summary


def main(tmp):
    checks, summary = validate(tmp / "a", "--python-solver", "honest=%s:Exact" % SOLVERS,
                               "--python-solver", "lossy=%s:LossyExact" % SOLVERS)
    assert summary["backends"]["lossy"]["exact"] and summary["backends"]["honest"]["exact"], summary["backends"]
    energy = checks[("lossy", "energy_drift")]
    assert energy["status"] == "fail", energy
    assert abs(energy["value"] - (1 - 0.995 ** 2)) < 1e-6, energy
    for backend in ("honest", "event-plain"):
        bad = [c for (b, _), c in checks.items() if b == backend and c["status"] == "fail"]
        assert not bad, bad
    # event-plain and the honest class get event's limits on the same case.
    for name in ("energy_drift", "max_overlap", "wall_penetration"):
        assert checks[("event-plain", name)]["tolerance"] == checks[("event", name)]["tolerance"] == \
            checks[("honest", name)]["tolerance"], name
    # Declaring nothing, the lossy solver passes the loose limit: the hole the declaration closes.
    loose, _ = validate(tmp / "b", "--python-solver", "lossy=%s:LossyUndeclared" % SOLVERS)
    assert loose[("lossy", "energy_drift")]["status"] == "pass", loose[("lossy", "energy_drift")]


def test_declared_exact_solver(tmp_path):
    main(tmp_path)


if __name__ == "__main__":
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        main(pathlib.Path(d))
    print("ok")
