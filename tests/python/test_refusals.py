# What Python refuses (docs/refusals.md, "From Python"): bad input raises a Python exception
# that names the key, never a crash; the CLI and Python refuse the same targets, states and
# backend options with the same words. Cases that crashed or hung the interpreter run in a
# child process, so that a regression fails the test instead of killing pytest.
import json
import pathlib
import re
import subprocess

import numpy as np
import pytest

import collide
from conftest import SMALL_GAS, backend_names, in_child

HERE = pathlib.Path(__file__).resolve().parent


def cli_error(collide_exe, scene_file, backend):
    """The CLI's message for `collide run SCENE --backend BACKEND`, which must fail."""
    done = subprocess.run([collide_exe, "run", str(scene_file), "--backend", backend], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode != 0, done.stdout
    line = [l for l in done.stderr.splitlines() if l.startswith("collide: error: ")][0]
    return line[len("collide: error: "):]


# ---- 9. Scene.from_dict: hostile values raise naming the key ------------------------------

FROM_DICT_CASES = {
    "numpy_array": ("{'description': 'x', 'seed': np.arange(3)}", "seed"),
    "self_reference": ("(lambda d: (d.__setitem__('world', d), d)[1])({'description': 'x'})", "world"),
    "nested_1e5_deep": ("{'description': 'x', 'world': deep(100000)}", "world"),
    "index_raises": ("{'description': 'x', 'seed': RaisingIndex()}", "seed"),
}


@pytest.mark.parametrize("case", sorted(FROM_DICT_CASES))
def test_9_from_dict_raises_naming_the_key_instead_of_crashing(case):
    value, key = FROM_DICT_CASES[case]
    out = in_child("""
        import json, numpy as np, collide
        class RaisingIndex:
            def __index__(self): raise ZeroDivisionError("no index")
        def deep(n):
            x = []
            for _ in range(n):
                x = [x]
            return x
        try:
            collide.Scene.from_dict(%s)
            print(json.dumps(["built", ""]))
        except Exception as e:
            print(json.dumps([type(e).__name__, str(e)]))
    """ % value)
    kind, message = out
    assert kind in ("ValueError", "TypeError", "SceneError"), out
    assert re.search(r"(^|[ .\]])%s\b" % key, message), out


def test_9_numpy_scalars_are_numbers_and_arrays_lists():
    out = in_child("""
        import json, numpy as np, collide
        scene = collide.Scene.from_dict({
            "description": "numpy values", "seed": np.int64(3),
            "world": {"box": np.array([0.0, 0.0, 10.0, 10.0])},
            "run": {"duration": np.float32(0.5), "output_interval": 0.1, "dt": 1e-3},
            "particles": [{"kind": "gas", "count": np.uint16(10), "radius": 0.5, "mass": 1.0,
                           "velocity": {"maxwell": np.float64(1.0)}}]})
        print(json.dumps([scene.seed, scene.box, scene.duration]))
    """)
    assert out == [3, [0.0, 0.0, 10.0, 10.0], 0.5]


# ---- 10. one check of the target time, on every backend, with the CLI's cap ----------------

TARGETS = {
    "nan": "target time t = nan is not a finite number",
    "inf": "target time t = inf is not a finite number",
    "1e300": "target time t = 1e+300: expected at most 1000000000000 steps of dt = 0.001 (this is 1e+303 steps)",
    "0.01": "target time t = 0.01 is in the past: the simulation is at t = 0.05 and never goes backwards",
}


@pytest.mark.parametrize("backend", backend_names())
def test_10_target_time_is_checked_on_every_backend(backend):
    # A child process: an infinite or huge target used to run for ever, deaf to Ctrl-C.
    out = in_child("""
        import json, sys, collide
        sys.path.insert(0, %r)
        from conftest import SMALL_GAS
        sim = collide.Simulation(collide.Scene.from_toml(SMALL_GAS, "small_gas"), backend=%r)
        sim.advance_to(0.05)
        before = sim.state_hash()
        out = {}
        for t in %r:
            try:
                sim.advance_to(float(t))
                out[t] = ["returned", sim.time]
            except Exception as e:
                out[t] = [type(e).__name__, str(e), sim.time, sim.state_hash() == before]
        sim.advance_to(0.1)  # still usable
        out["then"] = sim.time
        print(json.dumps(out))
    """ % (str(HERE), backend, sorted(TARGETS)), timeout=30)
    for t, words in TARGETS.items():
        assert out[t][:2] == ["ValueError", backend + ": " + words], out[t]
        assert out[t][2] == pytest.approx(0.05) and out[t][3], "the refused call changed the simulation"
    assert out["then"] == pytest.approx(0.1)


def test_10_advance_to_inf_returns_at_once():
    # On the event backend this looped for ever, deaf to Ctrl-C: a child process holds the hang.
    out = in_child("""
        import json, sys, collide
        sys.path.insert(0, %r)
        from conftest import SMALL_GAS
        sim = collide.Simulation(collide.Scene.from_toml(SMALL_GAS, "small_gas"), backend="event")
        try:
            sim.advance_to(float("inf"))
            print(json.dumps(["returned", sim.time]))
        except ValueError as e:
            print(json.dumps(["ValueError", str(e)]))
    """ % str(HERE), timeout=30)
    assert out == ["ValueError", "event: target time t = inf is not a finite number"]


def test_10_the_cap_has_the_scene_readers_words(tmp_path, collide_exe):
    # The CLI refuses duration = 1e300 with the words advance_to(1e300) gets (tested above).
    scene_file = tmp_path / "long.toml"
    scene_file.write_text(SMALL_GAS.replace("duration = 0.1", "duration = 1e300"))
    cli = cli_error(collide_exe, scene_file, "step")
    assert cli.endswith("duration = 1e+300: " + TARGETS["1e300"].split(": ", 1)[1])


# ---- 11. a non-finite state is refused; backend options are checked as a scene file's --------

HUGE_SPEEDS = """description = "two disks whose speeds overflow"
[world]
box = [0.0, 0.0, 10.0, 10.0]
[run]
duration = 0.2
output_interval = 0.1
dt = 1e-3
[[particles]]
kind = "list"
disks = [{ x = 2.0, y = 5.0, vx = 1e155, vy = 0.0, radius = 0.5, mass = 1.0 },
         { x = 8.0, y = 5.0, vx = -1e155, vy = 0.0, radius = 0.5, mass = 1.0 }]
"""


@pytest.mark.parametrize("backend", ["step", "cpu"])
def test_11_a_nonfinite_state_is_refused_with_the_clis_words(tmp_path, collide_exe, backend):
    # cpu: 1e155 is beyond float, so its state would hold Inf (the issue's "kinetic energy 0.0
    # beside nonfinite = 2"); step: the kinetic energy would overflow double although every disk
    # is finite. Both backends now refuse the scene before it starts (core/numerics/representability.h),
    # naming the quantity; Python raises the CLI's words. A state that breaks midway: below.
    scene_file = tmp_path / "huge_speeds.toml"
    scene_file.write_text(HUGE_SPEEDS)
    cli = cli_error(collide_exe, scene_file, backend)
    with pytest.raises(RuntimeError) as error:
        sim = collide.Simulation(collide.Scene.from_file(str(scene_file)), backend=backend)
        sim.advance_to(0.1)
    assert str(error.value) == cli
    assert "cannot run scene 'huge_speeds'" in cli and "overflows" in cli


BAD_OPTIONS = [("tc", "abc"), ("preset", "nope"), ("bogus", 1)]


@pytest.mark.parametrize("backend", [b for b in ("event", "step", "box2d") if b in backend_names()])
@pytest.mark.parametrize("key,value", BAD_OPTIONS)
def test_11_bad_backend_options_are_refused_as_in_a_scene_file(tmp_path, collide_exe, backend, key, value):
    # The same file without, then with the key: messages may name the file.
    scene_file = tmp_path / "small_gas.toml"
    scene_file.write_text(SMALL_GAS)
    scene = collide.Scene.from_file(str(scene_file))
    scene_file.write_text(SMALL_GAS + "\n[backend.%s]\n%s = %s\n" % (backend, key, json.dumps(value)))
    cli = cli_error(collide_exe, scene_file, backend)
    for make in (lambda: collide.Simulation(scene, backend=backend, **{key: value}),
                 lambda: collide.run(scene, backend, progress=False, **{key: value})):
        with pytest.raises((ValueError, RuntimeError)) as error:
            make()
        # The same words; the CLI's start with the file and line where the key was read.
        assert cli == str(error.value) or cli.endswith(": " + str(error.value)), (cli, str(error.value))


def test_11_good_backend_options_still_work(small_gas):
    a = collide.Simulation(small_gas, backend="event", tc=1e-3, prefetch="off")
    b = collide.Simulation(collide.Scene.from_toml(SMALL_GAS + '\n[backend.event]\ntc = 1e-3\nprefetch = "off"\n',
                                                   "small_gas"), backend="event")
    a.advance_to(0.1)
    b.advance_to(0.1)
    assert a.state_hash() == b.state_hash()


FALLING = """description = "one disk falling for ever through a periodic box"
[world]
box = [0.0, 0.0, 10.0, 10.0]
boundary = "periodic"
[physics]
gravity = [0.0, -1e38]
[run]
duration = 5.0
output_interval = 0.1
dt = 1e-3
[[particles]]
kind = "list"
disks = [{ x = 5.0, y = 5.0, vx = 0.0, vy = 0.0, radius = 0.5, mass = 1.0 }]
"""


def test_11_a_state_that_breaks_midway_is_refused_and_stays_readable(tmp_path, collide_exe):
    # In float, the speed g t passes 3.4e38 at t = 3.4: the CLI stops at its next output time.
    scene_file = tmp_path / "falling.toml"
    scene_file.write_text(FALLING)
    cli = cli_error(collide_exe, scene_file, "cpu")
    sim = collide.Simulation(collide.Scene.from_file(str(scene_file)), backend="cpu")
    with pytest.raises(RuntimeError) as error:
        for k in range(1, 51):
            sim.advance_to(k * 0.1)  # the CLI's output times
    assert str(error.value) == cli.replace("a smaller [run] output_interval", "advancing in smaller pieces")
    assert "every disk was finite at t = 3.4" in cli
    assert sim.positions.shape == (1, 2) and sim.metrics()["nonfinite"] == 1  # still readable
    with pytest.raises(RuntimeError, match="this simulation cannot go on"):
        sim.advance_to(5.0)


# ---- 12. integers beyond 64 bits name their key ---------------------------------------------

def test_12_integers_beyond_64_bits_name_their_key(small_gas):
    with pytest.raises(ValueError, match=r"^seed: integer 1180591620717411303424 does not fit in 64 bits"):
        collide.Scene.from_dict({"description": "x", "seed": 2**70})
    with pytest.raises(ValueError, match=r"^particles\[0\]\.count: an integer of 3322 bits does not fit in 64 bits"):
        collide.Scene.from_dict({"description": "x", "particles": [{"count": 10**1000}]})
    # -2^63 is refused too: the TOML writer cannot print it without overflow (found by UBSan).
    with pytest.raises(ValueError, match=r"^seed: integer -9223372036854775808 does not fit in 64 bits"):
        collide.Scene.from_dict({"description": "x", "seed": -2**63})
    with pytest.raises(collide.SceneError, match=r"seed = -9223372036854775807: expected an integer in \[0, 2\^32 - 1\]"):
        collide.Scene.from_dict({"description": "x", "seed": -2**63 + 1})  # written, then judged by the scene
    with pytest.raises(ValueError, match=r"^threads: integer 1180591620717411303424 does not fit in 64 bits"):
        collide.Simulation(small_gas, backend="cpu", threads=2**70)
    with pytest.raises(ValueError, match=r"^tc: integer 1180591620717411303424 does not fit in 64 bits"):
        collide.Simulation(small_gas, backend="event", tc=2**70)
