# Scenes from Python: a file, its TOML text and the same keys as a dict give the same scene
# (the same initial state, bit for bit), and a bad scene raises the CLI's message.
import subprocess

import pytest

import collide


def test_file_text_and_dict_give_the_same_initial_state(root):
    path = root / "data" / "scenes" / "box_gas_1000.toml"
    from_file = collide.Scene.from_file(str(path))
    from_text = collide.Scene.from_toml(path.read_text(), "box_gas_1000")
    from_dict = collide.Scene.from_dict({
        "description": "the same keys as data/scenes/box_gas_1000.toml",
        "seed": 1,
        "world": {"box": [0.0, 0.0, 50.0, 50.0], "boundary": "reflect"},
        "run": {"duration": 10.0, "output_interval": 0.1, "dt": 1e-3},
        "particles": [{"kind": "gas", "count": 1000, "radius": 0.5, "mass": 1.0, "velocity": {"maxwell": 1.0}}],
    })
    h = from_file.initial_state_hash()
    assert from_text.initial_state_hash() == h
    assert from_dict.initial_state_hash() == h
    assert from_file.name == from_text.name == "box_gas_1000"
    assert from_file.box == (0.0, 0.0, 50.0, 50.0) and from_file.dt == 1e-3


def test_dict_with_explicit_disks(root):
    # [[particles]] with an array of inline tables: a list of dicts inside a list of dicts.
    path = root / "data" / "scenes" / "head_on_equal.toml"
    d = {
        "description": "two disks", "seed": 1,
        "world": {"box": [0.0, 0.0, 10.0, 4.0], "boundary": "reflect"},
        "run": {"duration": 3.0, "output_interval": 0.1, "dt": 1e-3},
        "particles": [{"kind": "list", "disks": [
            {"x": 3.0, "y": 2.0, "vx": 1.0, "vy": 0.0, "radius": 0.5, "mass": 1.0},
            {"x": 7.0, "y": 2.0, "vx": -1.0, "vy": 0.0, "radius": 0.5, "mass": 1.0}]}],
    }
    assert collide.Scene.from_dict(d).initial_state_hash() == collide.Scene.from_file(str(path)).initial_state_hash()


def test_bad_scene_files_raise_the_cli_message(root, collide_exe):
    bad = sorted((root / "tests" / "data" / "bad_scenes").glob("*.toml"))
    assert bad
    for path in bad:
        rel = str(path.relative_to(root))
        cli = subprocess.run([collide_exe, "run", rel, "--backend", "step"], cwd=root,
                             capture_output=True, text=True, timeout=120)
        assert cli.returncode == 1, rel
        prefix = "collide: error: "
        assert cli.stderr.startswith(prefix), cli.stderr
        with pytest.raises(Exception) as info:
            collide.Simulation(collide.Scene.from_file(rel), backend="step")
        assert str(info.value) == cli.stderr[len(prefix):].rstrip("\n"), rel


def test_scene_error_is_a_value_error_naming_the_key():
    bad = {"description": "x", "world": {"box": [0, 0, 1, 1], "bogus": 1},
           "particles": [{"kind": "gas", "count": 1, "radius": 0.1}]}
    with pytest.raises(collide.SceneError) as info:
        collide.Scene.from_dict(bad, "mine")
    assert isinstance(info.value, ValueError)
    assert "unknown key [world].bogus" in str(info.value)
    assert str(info.value).startswith("mine:")
    # For a dict, the line is that of the TOML text made from it (collide.toml_from_dict).
    assert info.value.source == "mine"
    assert "bogus" in collide.toml_from_dict(bad).splitlines()[info.value.line - 1]
    assert info.value.detail == "unknown key [world].bogus: expected one of box, boundary"
    with pytest.raises(collide.SceneError, match="restitution = 1.5: expected a number in"):
        collide.Scene.from_toml('description = "x"\n[world]\nbox = [0, 0, 1, 1]\n[physics]\nrestitution = 1.5\n')


def test_dict_values_without_a_toml_form_raise_type_error():
    with pytest.raises(TypeError, match="world.box"):
        collide.Scene.from_dict({"description": "x", "world": {"box": object()}})
