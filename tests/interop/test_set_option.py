"""`--set PATH=VALUE` on run, view, explain and Python's Scene.with_overrides: the value takes
effect, is recorded in the run file's provenance, and a key or value the scene file could not
hold is refused with the message the file would get."""

import re
import subprocess

import h5py
import pytest

from conftest import SCENES

HEAD_ON = SCENES / "head_on_equal.toml"


def core_message(stderr):
    """The loader's message without the program's prefix, the file's line and the --set note."""
    text = stderr.strip().removeprefix("collide: error: ")
    text = re.sub(r"^.*?\.toml(:\d+)?: ", "", text)
    return re.sub(r" \(with --set .*\)$", "", text)


def edited_scene(tmp_path, old, new):
    text = HEAD_ON.read_text()
    assert old in text
    path = tmp_path / "head_on_equal.toml"
    path.write_text(text.replace(old, new))
    return path


def test_run_applies_the_overrides_and_records_them(run_collide, tmp_path):
    out = tmp_path / "run.h5"
    r = run_collide("run", HEAD_ON, "--out", out, "--set", "run.dt=2.5e-4", "--set", "world.boundary=periodic")
    assert r.returncode == 0, r.stderr
    assert "set       run.dt=2.5e-4; world.boundary=periodic" in r.stdout
    with h5py.File(out, "r") as f:
        assert f.attrs["scene_overrides"] == "run.dt=2.5e-4; world.boundary=periodic"
        assert f.attrs["dt"] == "0.00025"  # round-trip text (core/numerics/number_text.h)
        scene_text = f.attrs["scene_text"]
    # The recorded scene is the changed one: running it alone repeats the run.
    assert "periodic" in scene_text and "0.00025" in scene_text
    again = tmp_path / "again.toml"
    again.write_text(scene_text)
    r2 = run_collide("run", again, "--out", tmp_path / "again.h5")
    assert r2.returncode == 0, r2.stderr
    with h5py.File(out, "r") as a, h5py.File(tmp_path / "again.h5", "r") as b:
        assert (a["metrics/kinetic_energy"][()] == b["metrics/kinetic_energy"][()]).all()
        assert b.attrs["scene_overrides"] == ""


@pytest.mark.parametrize("override, in_file", [
    ("run.dtt=1", ("dt = ", "dtt = 1\ndt = ")),                     # an unknown key
    ("run.dt=-1", ("dt = 1e-3", "dt = -1")),                         # a value out of range
    ("physics.restitution=1.5", ("[run]", "[physics]\nrestitution = 1.5\n\n[run]")),
    ("world.boundary=sideways", ('boundary = "reflect"', 'boundary = "sideways"')),
])
def test_refusals_carry_the_message_the_file_would_get(run_collide, tmp_path, override, in_file):
    r = run_collide("run", HEAD_ON, "--set", override)
    assert r.returncode == 1 and r.stdout == ""
    assert str(HEAD_ON) in r.stderr and ("(with --set " + override + ")") in r.stderr, r.stderr
    as_file = run_collide("run", edited_scene(tmp_path, *in_file))
    assert as_file.returncode == 1
    assert core_message(r.stderr) == core_message(as_file.stderr), (r.stderr, as_file.stderr)


@pytest.mark.parametrize("override, expected", [
    ("particles.7.mass=1", "--set particles.7.mass=1: no element 7 in 'particles' (it has 1)"),
    ("description.x=1", "--set description.x=1: 'description' is a value, not a table or an array"),
    ("run.dt", "--set run.dt: expected PATH=VALUE"),
    ("run.dt=[1,", "--set run.dt=[1,: the value is no TOML value"),
])
def test_paths_that_lead_nowhere_are_refused(run_collide, override, expected):
    r = run_collide("run", HEAD_ON, "--set", override)
    assert r.returncode == 1 and expected in r.stderr, r.stderr


def test_view_takes_the_overrides_and_refuses_alike(run_collide, tmp_path):
    png = tmp_path / "last.png"
    r = run_collide("view", HEAD_ON, "--headless", "--frames", "3", "--screenshot", png, "--size", "64x64",
                    "--set", "run.output_interval=0.05")
    assert r.returncode == 0, r.stderr
    assert png.is_file()
    bad = run_collide("view", HEAD_ON, "--headless", "--frames", "3", "--set", "run.dtt=1")
    assert bad.returncode == 1 and "unknown key [run].dtt" in bad.stderr, bad.stderr


@pytest.fixture(scope="module")
def validated(tmp_path_factory, run_collide):
    folder = tmp_path_factory.mktemp("explain")
    suite = folder / "suite.toml"
    suite.write_text('name = "explain-set"\nbackends = ["event", "step"]\nreference = "event"\nseeds = [1]\n'
                     'scene_dir = "%s"\n\n[[scene]]\nname = "head_on_equal"\nduration = 2.0\ndt = [1e-3]\n' % SCENES)
    r = run_collide("validate", suite, "--out", folder / "out", "--jobs", "1")
    assert r.returncode == 0, r.stdout + r.stderr
    import json
    cases = json.loads((folder / "out" / "summary.json").read_text())["cases"]
    return folder / "out", next(c["id"] for c in cases if c["backend"] == "step")


def test_explain_reruns_the_case_with_the_overrides(run_collide, validated):
    out, case = validated
    plain = run_collide("explain", out, case)
    assert plain.returncode == 0, plain.stderr
    assert "set " not in plain.stdout
    what_if = run_collide("explain", out, case, "--set", "physics.restitution=0.5", "--set", "run.dt=2e-3")
    assert what_if.returncode == 0, what_if.stderr
    assert "set       physics.restitution=0.5; run.dt=2e-3 (a what-if rerun" in what_if.stdout
    assert "dt = 0.002" in what_if.stdout
    assert plain.stdout.splitlines()[2] != what_if.stdout.splitlines()[3], "an inelastic rule changes the jump"
    bad = run_collide("explain", out, case, "--set", "physics.restitutio=0.5")
    assert bad.returncode == 1 and "unknown key [physics].restitutio" in bad.stderr, bad.stderr
    bad = run_collide("explain", out, case, "--set", "run.dt=3e-3")  # 2.0 is no whole number of steps
    assert bad.returncode == 1 and "dt" in bad.stderr, bad.stderr


def test_python_scene_with_overrides(tmp_path):
    collide = pytest.importorskip("collide")
    scene = collide.Scene.from_file(str(HEAD_ON))
    changed = scene.with_overrides({"run.dt": 2.5e-4, "world.boundary": "periodic", "physics.gravity": [0.0, -1.0]})
    assert changed.dt == 2.5e-4 and changed.periodic and not scene.periodic
    assert changed.overrides == 'run.dt=0.00025; world.boundary="periodic"; physics.gravity=[0.0, -1.0]'
    result = collide.run(changed, "step", out=tmp_path / "run.h5", progress=False)
    assert result["out"]
    with h5py.File(tmp_path / "run.h5", "r") as f:
        assert f.attrs["scene_overrides"] == changed.overrides
    with pytest.raises(collide.SceneError, match=r"unknown key \[run\]\.dtt"):
        scene.with_overrides({"run.dtt": 1.0})
    with pytest.raises(collide.SceneError, match="expected a time step > 0"):
        scene.with_overrides({"run.dt": -1.0})
    with pytest.raises(TypeError):
        scene.with_overrides({"run.dt": object()})


def test_key_depth_is_bounded_on_the_command_line(collide_exe):
    # 60,000 parts built as many nested tables, destroyed recursively by toml++: with a 2 MiB
    # stack the program died by a signal. The bound is the scene file's (8 dotted parts).
    path = ".".join(["a"] * 60000)
    r = subprocess.run(["bash", "-c", 'ulimit -s 2048 && exec "$@"', "bash", collide_exe, "run", str(HEAD_ON),
                        "--set", path + "=1"], capture_output=True, text=True, stdin=subprocess.DEVNULL)
    assert r.returncode == 1, (r.returncode, r.stderr[-500:])
    assert "a path with more than 8 dotted parts (it has 60000)" in r.stderr and len(r.stderr) < 600, r.stderr
