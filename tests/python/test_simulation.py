# collide.Simulation: the state as NumPy arrays, advance_to in pieces, errors, Ctrl-C.
import signal

import numpy as np
import pytest

import collide
from conftest import backend_names


def test_state_arrays_are_read_only_float64_copies(small_gas):
    sim = collide.Simulation(small_gas, backend="event")
    sim.advance_to(0.05)
    for name in ("positions", "velocities", "radii", "masses"):
        a = getattr(sim, name)
        assert a.dtype == np.float64 and not a.flags.writeable
        assert a.shape == ((120, 2) if name in ("positions", "velocities") else (120,))
        with pytest.raises(ValueError):
            a[0] = 1.0
    positions = sim.positions
    kept = positions.copy()
    del sim  # the arrays own their memory: they outlive the simulation
    assert np.array_equal(positions, kept)


def test_metrics_and_stats_are_dicts(small_gas):
    sim = collide.Simulation(small_gas, backend="event")
    e0 = sim.metrics()["kinetic_energy"]
    sim.advance_to(0.1)
    m = sim.metrics()
    assert m["time"] == 0.1 and m["overlapping_pairs"] == 0 and m["nonfinite"] == 0
    assert m["kinetic_energy"] == pytest.approx(e0, rel=1e-12)  # elastic: conserved
    s = sim.stats()
    assert s["contacts"] > 0 and s["counters"]["events_pair"] == s["contacts"]
    assert isinstance(s["phase_seconds"], dict)
    assert sim.time == 0.1 and len(sim) == 120


@pytest.mark.parametrize("backend", backend_names())
def test_advance_in_pieces_equals_one_call(small_gas, backend):
    # The stepped backends step to the nearest whole dt, so uneven pieces still add up to the
    # same steps; the event solver processes the same events in the same order whatever times
    # it stops at. Either way the final state is the same bit for bit.
    one = collide.Simulation(small_gas, backend=backend)
    one.advance_to(0.1)
    pieces = collide.Simulation(small_gas, backend=backend)
    for t in np.linspace(0.0, 0.1, 38)[1:-1]:
        pieces.advance_to(float(t))
    pieces.advance_to(0.1)
    assert pieces.state_hash() == one.state_hash()
    assert np.array_equal(pieces.positions, one.positions)
    assert np.array_equal(pieces.velocities, one.velocities)
    assert pieces.metrics() == one.metrics()


def test_errors_keep_their_text_and_leave_other_simulations_alone(small_gas):
    a = collide.Simulation(small_gas, backend="event")
    b = collide.Simulation(small_gas, backend="event")
    a.advance_to(0.05)
    with pytest.raises(ValueError, match=r"event: target time t = 0.01 is in the past: the simulation is at t = 0.05"):
        a.advance_to(0.01)
    b.advance_to(0.1)
    a.advance_to(0.1)  # refused calls change nothing
    assert a.state_hash() == b.state_hash()
    with pytest.raises(ValueError, match="unknown backend 'nope'; available: event"):
        collide.Simulation(small_gas, backend="nope")


def test_backend_that_cannot_run_the_scene_says_why(root):
    periodic = collide.Scene.from_file(str(root / "data" / "scenes" / "periodic_gas.toml"))
    if "box2d" not in backend_names():
        pytest.skip("no box2d in this build")
    with pytest.raises(ValueError, match="backend 'box2d' cannot run scene 'periodic_gas'"):
        collide.Simulation(periodic, backend="box2d")


def test_ctrl_c_raises_keyboard_interrupt_and_leaves_a_usable_simulation(root):
    sim = collide.Simulation(collide.Scene.from_file(str(root / "data" / "scenes" / "box_gas_1000.toml")), "event")
    signal.setitimer(signal.ITIMER_REAL, 0.3)
    old = signal.signal(signal.SIGALRM, lambda *_: signal.raise_signal(signal.SIGINT))
    try:
        with pytest.raises(KeyboardInterrupt):
            sim.advance_to(1e6)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    t = sim.time
    assert 0 < t < 1e6
    assert sim.metrics()["overlapping_pairs"] == 0
    sim.advance_to(t + 0.1)
    assert sim.time == t + 0.1


def test_gil_released_while_advancing_and_other_threads_are_told_to_wait(root):
    import threading
    import time
    sim = collide.Simulation(collide.Scene.from_file(str(root / "data" / "scenes" / "box_gas_1000.toml")), "event")
    worker = threading.Thread(target=sim.advance_to, args=(100.0,))  # long enough (~10^5 collisions) to be caught
    worker.start()
    refused = 0
    while worker.is_alive():  # this loop runs at all only because advance_to released the GIL
        try:
            sim.positions
        except RuntimeError as e:
            assert "advancing in another thread" in str(e)
            refused += 1
        time.sleep(0.01)
    worker.join()
    assert refused > 0
    assert sim.time == 100.0 and sim.metrics()["overlapping_pairs"] == 0
