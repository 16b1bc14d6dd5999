# The Python module and the `collide run` program are the same code: the same scene on the same
# backend gives the same metric series and final state, bit for bit (read from the CLI's HDF5).
import subprocess

import h5py
import numpy as np
import pytest

import collide
from conftest import SMALL_GAS, backend_names


@pytest.mark.parametrize("backend", backend_names())
def test_python_run_and_cli_run_are_bit_identical(tmp_path, collide_exe, backend):
    scene_file = tmp_path / "small_gas.toml"
    scene_file.write_text(SMALL_GAS)
    cli_out = tmp_path / "cli.h5"
    subprocess.run([collide_exe, "run", str(scene_file), "--backend", backend, "--out", str(cli_out), "--frames"],
                   check=True, capture_output=True, timeout=300)
    scene = collide.Scene.from_file(str(scene_file))
    py_out = tmp_path / "py.h5"
    result = collide.run(scene, backend, out=py_out, frames=True, progress=False)
    sim = collide.Simulation(scene, backend=backend)
    sim.advance_to(scene.duration)

    with h5py.File(cli_out, "r") as cli, h5py.File(py_out, "r") as py:
        for name, series in result["metrics"].items():
            if name == "total_energy":
                continue  # derived (kinetic + potential), not stored
            assert series.dtype == cli["metrics"][name].dtype, name
            assert np.array_equal(series, cli["metrics"][name][...]), name
            assert np.array_equal(py["metrics"][name][...], cli["metrics"][name][...]), name
        final_x, final_v = cli["frames/position"][-1], cli["frames/velocity"][-1]
        assert np.array_equal(py["frames/position"][...], cli["frames/position"][...])
        assert cli.attrs["backend"] == py.attrs["backend"] == backend
        assert cli.attrs["scene_text"] == py.attrs["scene_text"]
        assert dict(cli["stats"].attrs) == dict(py["stats"].attrs)
    assert np.array_equal(result["positions"], final_x) and np.array_equal(result["velocities"], final_v)
    assert np.array_equal(sim.positions, final_x) and np.array_equal(sim.velocities, final_v)
    assert sim.state_hash() == result["state_hash"]
    last = {k: v[-1] for k, v in result["metrics"].items()}
    assert sim.metrics() == pytest.approx(last, rel=0, abs=0)


def test_run_without_output_returns_arrays(small_gas):
    result = collide.run(small_gas, "event", progress=False)
    assert result["out"] is None
    assert result["time"].tolist() == pytest.approx([0.0, 0.02, 0.04, 0.06, 0.08, 0.1])
    assert result["kinetic_energy"] is result["metrics"]["kinetic_energy"]
    assert not result["kinetic_energy"].flags.writeable
    assert result["stats"]["contacts"] > 0


def test_run_refuses_frames_without_a_file(small_gas):
    with pytest.raises(ValueError, match="frames=True needs out="):
        collide.run(small_gas, "event", frames=True)


def test_run_into_a_missing_directory_fails_before_running(small_gas, tmp_path):
    with pytest.raises(RuntimeError, match="no_such_dir"):
        collide.run(small_gas, "event", out=tmp_path / "no_such_dir" / "x.h5", progress=False)


def test_ctrl_c_in_run_leaves_no_file(tmp_path, root):
    import signal
    text = (root / "data" / "scenes" / "box_gas_1000.toml").read_text().replace("duration = 10.0", "duration = 500.0")
    scene = collide.Scene.from_toml(text, "long_gas")
    out = tmp_path / "run.h5"
    signal.setitimer(signal.ITIMER_REAL, 0.3)
    old = signal.signal(signal.SIGALRM, lambda *_: signal.raise_signal(signal.SIGINT))
    try:
        with pytest.raises(KeyboardInterrupt):
            collide.run(scene, "event", out=out, progress=False)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    assert list(tmp_path.iterdir()) == []  # neither the file nor its temporary
