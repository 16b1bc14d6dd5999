"""`collide export` and `collide.export`: each format read back by a reader that is not ours
(XDMF through meshio's TimeSeriesReader, GSD through the gsd package, extended XYZ through ASE)
and compared with the run file it came from: positions, radii and times bit for bit where the
format holds doubles, and as float32 roundings bit for bit where HOOMD's schema fixes float32.
"""

import os
import stat
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest

from conftest import SCENES, SOURCE


@pytest.fixture(scope="module")
def run_file(tmp_path_factory, run_collide):
    """stones_and_gas (200 disks and 5 stones) for 0.3 time units on `step`, with frames."""
    folder = tmp_path_factory.mktemp("exports")
    out = folder / "run.h5"
    r = run_collide("run", SCENES / "stones_and_gas.toml", "--backend", "step", "--frames", "--out", out,
                    "--set", "run.duration=0.3")
    assert r.returncode == 0, r.stderr
    with h5py.File(out, "r") as f:
        truth = {name: f[name][()] for name in ("frames/time", "frames/position", "frames/velocity",
                                                  "particles/radius", "particles/mass", "particles/inv_mass")}
    assert truth["frames/time"].size == 4 and truth["particles/radius"].size == 205
    return out, truth


def exported(run_collide, run, name, *extra):
    out = run.parent / name
    r = run_collide("export", run, "--out", out, *extra)
    assert r.returncode == 0, r.stderr
    assert out.is_file()
    return out


# --- XDMF: the XDMF file and its data beside it (NAME.frames.h5, plain per-frame datasets),
# read back through meshio's TimeSeriesReader: the points of the first frame, and each frame's
# time, position, velocity, radius and mass.

def test_xdmf_reads_back_bit_for_bit_through_meshios_time_series_reader(run_file, run_collide):
    meshio_xdmf = pytest.importorskip("meshio.xdmf")
    run, truth = run_file
    xdmf = exported(run_collide, run, "run.xdmf")
    assert (run.parent / "run.frames.h5").is_file()
    n = truth["particles/radius"].size
    with meshio_xdmf.TimeSeriesReader(xdmf) as reader:  # it refused the HyperSlab items (ReadError)
        points, cells = reader.read_points_cells()
        assert np.array_equal(points[:, :2], truth["frames/position"][0]) and not points[:, 2].any()
        assert [c.type for c in cells] == ["vertex"] and np.array_equal(cells[0].data.ravel(), np.arange(n))
        assert reader.num_steps == truth["frames/time"].size
        for k in range(reader.num_steps):
            t, point_data, _ = reader.read_data(k)
            assert t == truth["frames/time"][k]
            assert np.array_equal(point_data["position"][:, :2], truth["frames/position"][k])
            assert np.array_equal(point_data["velocity"][:, :2], truth["frames/velocity"][k])
            assert not point_data["velocity"][:, 2].any()
            for name in ("radius", "mass"):
                assert np.array_equal(point_data[name], truth["particles/" + name])


def test_xdmf_holds_no_hyperslab_and_names_its_data_file_beside_itself(run_file, run_collide, tmp_path):
    run, _ = run_file
    (tmp_path / "views").mkdir()
    xdmf = tmp_path / "views" / "run.xdmf"
    assert run_collide("export", run, "--out", xdmf).returncode == 0
    root = ET.parse(xdmf).getroot()
    items = root.findall(".//DataItem")
    assert items and all(i.get("Format") == "HDF" and i.get("ItemType") is None for i in items)
    for grid in root.findall(".//Grid[@GridType='Uniform']"):  # each frame has its own points (ParaView)
        assert grid.find("Geometry").get("GeometryType") == "XYZ"
    files = {i.text.split(":")[0] for i in items}
    assert files == {"run.frames.h5"} and (xdmf.parent / "run.frames.h5").is_file()


def test_gsd_reads_back_in_the_hoomd_schema(run_file, run_collide):
    hoomd = pytest.importorskip("gsd.hoomd")
    run, truth = run_file
    out = exported(run_collide, run, "run.gsd")
    centre = np.array([20.0, 10.0])  # the box is [0, 0, 40, 20]
    with hoomd.open(str(out), "rb") as trajectory:
        assert len(trajectory) == truth["frames/time"].size
        for k, frame in enumerate(trajectory):
            assert frame.configuration.dimensions == 2
            assert np.array_equal(frame.configuration.box, np.float32([40, 20, 0, 0, 0, 0]))
            p = frame.particles
            assert p.N == truth["particles/radius"].size
            # HOOMD's schema stores float32: the export is the float32 rounding of each double.
            assert np.array_equal(p.position[:, :2], (truth["frames/position"][k] - centre).astype(np.float32))
            assert not p.position[:, 2].any()
            assert np.array_equal(p.velocity[:, :2], truth["frames/velocity"][k].astype(np.float32))
            assert np.array_equal(p.diameter, (2 * truth["particles/radius"]).astype(np.float32))
            assert np.array_equal(p.mass, truth["particles/mass"].astype(np.float32))
            assert list(p.types) == ["disk", "stone"]
            assert np.array_equal(p.typeid, (truth["particles/inv_mass"] == 0).astype(np.uint32))
            assert (p.typeid == 1).sum() == 5
            assert frame.log["collide/time"][0] == truth["frames/time"][k]  # float64, exact
            assert np.array_equal(frame.log["collide/box_centre"], centre)


def test_extended_xyz_reads_back_bit_for_bit_with_ase(run_file, run_collide):
    ase_io = pytest.importorskip("ase.io")
    run, truth = run_file
    out = exported(run_collide, run, "run.xyz")
    frames = ase_io.read(str(out), index=":", format="extxyz")
    assert len(frames) == truth["frames/time"].size
    for k, atoms in enumerate(frames):
        assert atoms.info["Time"] == truth["frames/time"][k]
        assert np.array_equal(atoms.positions[:, :2], truth["frames/position"][k])
        assert not atoms.positions[:, 2].any()
        assert np.array_equal(atoms.arrays["radius"], truth["particles/radius"])
        assert np.array_equal(atoms.arrays["mass"], truth["particles/mass"])
        assert np.array_equal(atoms.arrays["vel"][:, :2], truth["frames/velocity"][k])
        assert np.array_equal(atoms.arrays["stone"], (truth["particles/inv_mass"] == 0).astype(int))
        assert set(atoms.get_chemical_symbols()) == {"X"}
        assert list(atoms.pbc) == [False, False, False]
        assert np.array_equal(atoms.cell[:2, :2], [[40, 0], [0, 20]])


def test_a_run_without_frames_is_refused_naming_the_flag(run_collide, tmp_path):
    run = tmp_path / "plain.h5"
    assert run_collide("run", SCENES / "head_on_equal.toml", "--out", run).returncode == 0
    for name in ("a.xdmf", "a.gsd", "a.xyz"):
        r = run_collide("export", run, "--out", tmp_path / name)
        assert r.returncode == 1
        assert "--frames" in r.stderr and str(run) in r.stderr, r.stderr
        assert not (tmp_path / name).exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plain.h5"], "nothing is left behind"


def test_an_unknown_format_is_refused(run_file, run_collide):
    run, _ = run_file
    r = run_collide("export", run, "--out", run.parent / "a.vtk")
    assert r.returncode == 1 and "--format" in r.stderr and ".xdmf, .gsd or .xyz" in r.stderr, r.stderr


def test_python_export_writes_what_the_program_writes(run_file, run_collide):
    collide = pytest.importorskip("collide")
    run, truth = run_file
    cli = exported(run_collide, run, "run.xyz")
    ours = run.parent / "python-run.xyz"
    assert collide.export(run, ours) == str(ours)
    assert ours.read_bytes() == cli.read_bytes()
    cli = exported(run_collide, run, "run.xdmf")
    ours = run.parent / "python-run.xdmf"  # its data: python-run.frames.h5
    collide.export(run, ours)
    assert ours.read_text() == cli.read_text().replace("run.frames.h5", "python-run.frames.h5")
    with h5py.File(run.parent / "run.frames.h5", "r") as a, h5py.File(run.parent / "python-run.frames.h5", "r") as b:
        assert np.array_equal(a["frames/3/position"][()], b["frames/3/position"][()])
    ours = run.parent / "python.gsd"
    collide.export(run, ours)
    hoomd = pytest.importorskip("gsd.hoomd")
    with hoomd.open(str(ours), "rb") as trajectory:
        assert [f.log["collide/time"][0] for f in trajectory] == list(truth["frames/time"])


# --- the GSD writer goes through the output guard (python/collide/safe_output.py) -------------

def test_gsd_writer_uses_the_output_guard(run_file, tmp_path, monkeypatch):
    """A link is followed (its file replaced, the link kept); a FIFO put at the path during the
    export is refused and left a FIFO (the writer renamed its file over both)."""
    pytest.importorskip("gsd.hoomd")
    sys.path.insert(0, str(SOURCE / "python" / "collide"))  # as `collide export` runs it: a script
    import gsd_export
    run, _ = run_file
    real, link = tmp_path / "real.gsd", tmp_path / "link.gsd"
    real.write_text("old")
    link.symlink_to(real)
    gsd_export.write_gsd(str(run), str(link))
    assert link.is_symlink() and real.read_bytes()[:3] != b"old"
    planted = tmp_path / "planted.gsd"
    frame = gsd_export._frame

    def plant_a_fifo(*args):
        if not planted.exists():
            os.mkfifo(planted)
        return frame(*args)

    monkeypatch.setattr(gsd_export, "_frame", plant_a_fifo)
    with pytest.raises(gsd_export.safe_output.OutputPathError, match="a FIFO"):
        gsd_export.write_gsd(str(run), str(planted))
    assert stat.S_ISFIFO(os.lstat(planted).st_mode)
    assert not [p for p in os.listdir(tmp_path) if ".tmp-" in p]


def test_xdmf_export_refuses_its_own_run_as_its_data_file(run_file, tmp_path):
    """NAME.xdmf writes NAME.frames.h5: a run file of that name is the input, refused."""
    collide = pytest.importorskip("collide")
    run, _ = run_file
    copy = tmp_path / "a.frames.h5"
    copy.write_bytes(run.read_bytes())
    with pytest.raises(Exception, match="it is the input"):
        collide.export(copy, tmp_path / "a.xdmf")
    assert copy.read_bytes() == run.read_bytes()
