# Hostile input to the Python module (docs/refusals.md, "From Python: hostile input"): each
# class of fault that killed the interpreter or silently did something else now raises a Python
# exception that says what is wrong. Calls that crashed run in a child process, so that a
# regression fails the test instead of killing pytest.
import os
import pathlib

import numpy as np
import pytest

import collide
from collide import solver_runner
from conftest import SMALL_GAS, in_child

HERE = pathlib.Path(__file__).resolve().parent


# ---- No std::regex on input text: a 60,000-character path is split by hand -----------------

def test_no_regex_on_input_text():
    # The message quotes the path; std::regex recursed once per character and overflowed.
    out = in_child("""
        import json, collide
        try:
            collide.Scene.from_file("x" * 60000)
        except collide.SceneError as e:
            print(json.dumps([len(e.source), e.line, e.detail[:80]]))
    """)
    assert out[0] == 60000 and out[1] is None, out


def test_no_regex_on_input_text_keeps_the_parts():
    with pytest.raises(collide.SceneError) as info:
        collide.Scene.from_toml(SMALL_GAS.replace("[world]\n", "[world]\nbogus = 1\n"), "mine: 2.toml")
    assert (info.value.source, info.value.line) == ("mine: 2.toml", 5), str(info.value)
    assert info.value.detail.startswith("unknown key [world].bogus"), str(info.value)
    with pytest.raises(collide.SceneError) as info:
        collide.Scene.from_file("/no/such/scene.toml")
    assert (info.value.source, info.value.line) == ("/no/such/scene.toml", None), str(info.value)


# ---- Key depth: one bound (8 dotted parts) for --set, suite sweeps and with_overrides ---------

def test_key_depth_is_bounded():
    # 150,000 parts built 150,000 nested tables; toml++ destroyed them recursively (a crash).
    out = in_child("""
        import json, sys, collide
        sys.path.insert(0, %r)
        from conftest import SMALL_GAS
        scene = collide.Scene.from_toml(SMALL_GAS, "small_gas")
        out = []
        for parts in (9, 150000):
            try:
                scene.with_overrides({".".join(["a"] * parts): 1})
                out.append("accepted")
            except collide.SceneError as e:
                out.append(str(e))
        print(json.dumps(out))
    """ % str(HERE))
    for message in out:
        assert "more than 8 dotted parts" in message and len(message) < 400, message


def test_override_values_are_read_as_from_dict():
    # A value 10^5 deep recursed in the conversion to TOML text (a crash); it is now read under
    # Scene.from_dict's rules first: at most 64 levels, no container that holds itself.
    out = in_child("""
        import json, sys, collide
        sys.path.insert(0, %r)
        from conftest import SMALL_GAS
        scene = collide.Scene.from_toml(SMALL_GAS, "small_gas")
        deep = []
        for _ in range(100000):
            deep = [deep]
        loop = {}
        loop["x"] = loop
        out = []
        for value in (deep, loop, None):
            try:
                scene.with_overrides({"physics.gravity": value})
                out.append("accepted")
            except (TypeError, ValueError) as e:
                out.append(str(e))
        print(json.dumps(out))
    """ % str(HERE))
    assert out[0].startswith("physics.gravity[0]") and "nested more than 64 levels" in out[0], out
    assert out[1].startswith("physics.gravity") and "contains itself" in out[1], out
    assert out[2] == "with_overrides: physics.gravity = None: expected a TOML value", out


def test_key_depth_bound_leaves_shallow_keys_to_the_loader(small_gas):
    with pytest.raises(collide.SceneError, match="unknown key") as info:
        small_gas.with_overrides({"a.a.a.a.a.a.a.a": 1})
    assert "dotted parts" not in str(info.value)


# ---- Control characters in keys: refused by path, never handed to the TOML reader --------------

def test_keys_with_control_characters_are_refused_by_path():
    # toml++ 3.3 writes a key holding a tab or a line break into a table header unquoted, and
    # its reader then stopped a debug build with an assertion (the fuzz test's case 1920 of
    # seed 31). Such keys are refused before any TOML is written, naming the key's path.
    out = in_child("""
        import json, sys, collide
        sys.path.insert(0, %r)
        from conftest import SMALL_GAS
        scene = collide.Scene.from_toml(SMALL_GAS, "small_gas")
        calls = [lambda: collide.Scene.from_dict({"\\n": {"a": 1}}),
                 lambda: collide.Scene.from_dict({"world": {"a\\tb": 1}}),
                 lambda: collide.Scene.from_dict({"run": {"\\x7f": {"b": 2}}}),
                 lambda: scene.with_overrides({"physics": {"x\\ry": 1}})]
        out = []
        for call in calls:
            try:
                call()
                out.append("accepted")
            except Exception as e:
                out.append([type(e).__name__, str(e)])
        print(json.dumps(out))
    """ % str(HERE))
    assert out[0] == ["ValueError", '"\\u000a": a key must not hold control characters'], out
    assert out[1] == ["ValueError", 'world."a\\u0009b": a key must not hold control characters'], out
    assert out[2] == ["ValueError", 'run."\\u007f": a key must not hold control characters'], out
    assert out[3][0] == "ValueError" and out[3][1].endswith('"x\\u000dy": a key must not hold control characters'), out


# ---- Uninitialised objects: every method and property raises TypeError ----------------------

def test_uninitialised_objects_raise():
    # Simulation.__new__(Simulation).time read through a null pointer (a crash).
    out = in_child("""
        import json, collide
        ARGUMENTS = {"with_overrides": ({"run.dt": 1e-3},), "advance_to": (0.1,)}
        out = {}
        for cls in (collide.Scene, collide.Simulation):
            for name in sorted(n for n in dir(cls) if not n.startswith("_")) + ["__len__", "__repr__"]:
                if not hasattr(cls, name):
                    continue
                obj = cls.__new__(cls)
                try:
                    value = getattr(obj, name)
                    if callable(value):
                        value(*ARGUMENTS.get(name, ()))
                    out[cls.__name__ + "." + name] = "returned"
                except Exception as e:
                    out[cls.__name__ + "." + name] = type(e).__name__ + ": " + str(e)
        print(json.dumps(out))
    """)
    static = {"Scene.from_file", "Scene.from_toml", "Scene.from_dict"}  # no object: they raise for the arguments
    assert "Simulation.time" in out and "Scene.with_overrides" in out
    for name, what in out.items():
        if name not in static:
            assert what.startswith("TypeError: ") and "is not initialised" in what, (name, what)


def test_uninitialised_objects_raise_when_self_is_none():
    out = in_child("""
        import json, collide
        out = []
        for call in (lambda: collide.Simulation.time.fget(None), lambda: collide.Simulation.__len__(None),
                     lambda: collide.Scene.periodic.fget(None), lambda: collide.Simulation.stats(None)):
            try:
                call()
                out.append("returned")
            except TypeError as e:
                out.append("TypeError")
        print(json.dumps(out))
    """)
    assert out == ["TypeError"] * 4


def test_uninitialised_objects_raise_as_arguments(small_gas):
    with pytest.raises(TypeError, match="is not initialised"):
        collide.Simulation(collide.Scene.__new__(collide.Scene))
    with pytest.raises(TypeError, match="is not initialised"):
        collide.run(collide.Scene.__new__(collide.Scene), progress=False)


# ---- The Python solver runner checks each answer's shape and dtype exactly -------------------

SOLVER = '''
import numpy as np

class Answers:
    def load(self, scene, initial):
        self.n = len(initial["radius"])
        self.good = initial["positions"]
    def advance_to(self, t):
        pass
    @property
    def positions(self):
        return {bad}
    @property
    def velocities(self):
        return np.zeros_like(self.good)
'''

BAD_ANSWERS = {
    "one_row": ("np.zeros((1, 2))", "shape (1, 2)"),
    "flat": ("np.zeros(self.n)", "shape (%d,)"),
    "transposed": ("np.zeros((2, self.n))", "shape (2, %d)"),
    "scalar": ("0.0", "a float"),
    "list": ("self.good.tolist()", "a list"),
    "none": ("None", "None"),
    "strings": ("np.full((self.n, 2), '1.5')", "dtype <U3"),
    "complex": ("self.good.astype(complex)", "dtype complex128"),
    "integers": ("self.good.astype(np.int64)", "dtype int64"),
    "float32": ("self.good.astype(np.float32)", "dtype float32"),
}


def request_directory(tmp_path, disks):
    """A request as collide writes it (docs/your-solver.md): request.txt, scene.toml, initial.npy."""
    directory = tmp_path / "request"
    directory.mkdir()
    (directory / "request.txt").write_text("protocol 1\ndisks %d\noutput_times 0.1 0.2\n" % disks)
    (directory / "scene.toml").write_text(SMALL_GAS)
    initial = np.zeros((disks, 7))
    initial[:, 0] = np.arange(disks)
    initial[:, 4:6] = 1.0
    np.save(directory / "initial.npy", initial)
    return directory


@pytest.mark.parametrize("case", sorted(BAD_ANSWERS))
def test_solver_answers_are_checked_exactly(tmp_path, case):
    bad, said = BAD_ANSWERS[case]
    disks = 3
    (tmp_path / "answers.py").write_text(SOLVER.format(bad=bad))
    directory = request_directory(tmp_path, disks)
    with pytest.raises(SystemExit) as info:
        solver_runner.run(str(tmp_path / "answers.py") + ":Answers", str(directory))
    message = str(info.value.code)
    assert "Answers.positions" in message and "at t = 0.1" in message, message
    assert ("%d, 2" % disks) in message and "float64" in message, message
    assert (said % disks if "%d" in said else said) in message, message
    assert not (directory / "states.npy").exists()


def test_solver_answers_of_the_right_form_pass(tmp_path):
    (tmp_path / "answers.py").write_text(SOLVER.format(bad="self.good.astype('>f8')"))
    directory = request_directory(tmp_path, 3)
    solver_runner.run(str(tmp_path / "answers.py") + ":Answers", str(directory))
    states = np.load(directory / "states.npy")
    assert states.shape == (2, 3, 4) and (states[:, :, 0] == np.arange(3)).all()


# ---- A NUL in a path argument is refused, never cut ------------------------------------------

def test_nul_in_paths_is_refused(tmp_path, small_gas, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = collide.run(small_gas, "step", out="run.h5", frames=True, progress=False)
    calls = {
        "run": lambda: collide.run(small_gas, "step", out="a\0b", progress=False),
        "export xyz": lambda: collide.export("run.h5", "a\0b.xyz"),
        "export xdmf": lambda: collide.export("run.h5", "a\0b.xdmf"),
        "export from": lambda: collide.export("run.h5\0x", "c.xyz"),
        "read_run": lambda: collide.read_run("run.h5\0x"),
        "from_file": lambda: collide.Scene.from_file(pathlib.Path("s\0.toml")),
        "validate": lambda: collide.validate("suite.toml", "a\0b"),
    }
    for name, call in calls.items():
        with pytest.raises(ValueError, match=r"holds a NUL character \(at byte \d+\)"):
            call()
    assert sorted(os.listdir(tmp_path)) == ["run.h5"], "a refused call wrote a file"
    assert result["out"] == "run.h5"


def test_nul_check_keeps_paths_of_any_bytes(tmp_path, small_gas):
    # bytes paths and names that are not UTF-8 reach the file system as they are (os.fsencode)
    out = os.fsencode(str(tmp_path)) + b"/r\xff.h5"
    collide.run(small_gas, "step", out=out, progress=False)
    assert os.path.exists(out)
    assert collide.read_run(out)["metrics"]["time"][-1] == pytest.approx(0.1)


# ---- A class whose module is not in sys.modules is not "a built-in class" ---------------------

def test_class_origin_is_named_for_what_it_is():
    Orphan = type("Orphan", (), {"__module__": "module_that_was_never_imported"})
    with pytest.raises(ValueError) as info:
        collide.validate("suite.toml", solvers={"mine": Orphan})
    message = str(info.value)
    assert "built-in" not in message, message
    assert "module_that_was_never_imported" in message and "sys.modules" in message, message
    with pytest.raises(ValueError, match="top level of a .py file"):
        collide.validate("suite.toml", solvers={"mine": int})
