# collide.read_run reads a run file through the C++ checked reader (core/io/run_reader.h): the
# columns of the run schema come back as h5py reads them, and a damaged file is refused.
import h5py
import numpy as np
import pytest

import collide


def test_read_run_matches_the_file(small_gas, tmp_path):
    out = tmp_path / "run.h5"
    result = collide.run(small_gas, "step", out=out, frames=True, progress=False)
    run = collide.read_run(out, frames=True)
    with h5py.File(out, "r") as f:
        assert sorted(run["metrics"]) == sorted(list(f["metrics"]) + ["total_energy"])
        for name in f["metrics"]:
            assert run["metrics"][name].dtype == f["metrics"][name].dtype, name
            assert np.array_equal(run["metrics"][name], f["metrics"][name][...]), name
        assert np.array_equal(run["positions"], f["frames/position"][...])
        assert np.array_equal(run["velocities"], f["frames/velocity"][...])
        assert np.array_equal(run["particles"]["radius"], f["particles/radius"][...])
        assert run["attributes"]["scene_text"] == f.attrs["scene_text"]
        assert run["stats"]["steps"] == f["stats"].attrs["steps"] > 0
        assert run["stats"]["contacts"] == f["stats"].attrs["contacts"]
        assert run["stats"]["phase_seconds"] == dict(f["stats/phase_seconds"].attrs) != {}
        assert run["stats"]["counters"] == dict(f["stats/counters"].attrs)
    for name, series in result["metrics"].items():
        assert np.array_equal(run["metrics"][name], series), name
    assert not run["metrics"]["time"].flags.writeable


def test_read_run_without_frames(small_gas, tmp_path):
    out = tmp_path / "run.h5"
    collide.run(small_gas, "event", out=out, progress=False)
    run = collide.read_run(out)
    assert run["has_frames"] is False and "positions" not in run
    with pytest.raises(ValueError, match="without frames"):
        collide.read_run(out, frames=True)


def test_read_run_refuses_a_damaged_file(small_gas, tmp_path):
    out = tmp_path / "run.h5"
    collide.run(small_gas, "event", out=out, progress=False)
    with h5py.File(out, "r+") as f:
        f.attrs["scene_text"] = "edited"  # no longer matches /attributes_checksum
    with pytest.raises(RuntimeError, match="checksum"):
        collide.read_run(out)


def test_read_run_names_a_missing_file(tmp_path):
    with pytest.raises(RuntimeError, match="no_such.h5"):
        collide.read_run(tmp_path / "no_such.h5")


def test_read_run_refuses_a_fifo_at_once(tmp_path):
    """Non-regular inputs are refused: a FIFO given as the run file was waited on for good. In a
    child process with a time limit, so that a wait fails this test instead of hanging it."""
    import os
    import subprocess
    import sys
    fifo = tmp_path / "run.h5"
    os.mkfifo(fifo)
    code = f"import collide\ntry:\n    collide.read_run({str(fifo)!r})\nexcept Exception as e:\n    print(e)\n"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert "not a regular file (it is a FIFO)" in r.stdout, r.stdout + r.stderr
