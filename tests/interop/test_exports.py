"""`collide export` and `collide.export`: each format read back by a reader that is not ours
(the XDMF's data items through meshio, GSD through the gsd package, extended XYZ through ASE)
and compared with the run file it came from: positions, radii and times bit for bit where the
format holds doubles, and as float32 roundings bit for bit where HOOMD's schema fixes float32.
"""

import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest

from conftest import SCENES


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


# --- XDMF: meshio 5 reads XDMF's HDF and XML data items but not HyperSlab items, nor points
# that move from one time to the next; so the HyperSlab items are composed here, from the XDMF
# model (start, stride and count rows, then the data), and every leaf is read by meshio's own
# reader (file path relative to the XDMF file, type, precision, shape).

def evaluate(item, reader):
    kind = item.get("ItemType")
    if kind == "HyperSlab":
        selection, data = [evaluate(c, reader) for c in item]
        start, stride, count = selection.astype(int)
        index = tuple(slice(s, s + st * c, st) for s, st, c in zip(start, stride, count))
        return data[index]
    assert kind is None, kind  # no Function items: their meaning differs between XDMF 2 and 3
    return reader._read_data_item(item)


def test_xdmf_points_into_the_run_file_and_reads_back_bit_for_bit(run_file, run_collide):
    meshio_xdmf = pytest.importorskip("meshio.xdmf")
    run, truth = run_file
    xdmf = exported(run_collide, run, "run.xdmf")
    assert xdmf.stat().st_size < 40_000, "the XDMF file points into the run file, it copies nothing"
    reader = meshio_xdmf.TimeSeriesReader(xdmf)  # checks Xdmf 3, Domain, a Temporal collection
    assert reader.num_steps == truth["frames/time"].size
    n = truth["particles/radius"].size
    for k, grid in enumerate(reader.collection):
        assert grid.get("GridType") == "Uniform"
        assert float(grid.find("Time").get("Value")) == truth["frames/time"][k]
        topology = grid.find("Topology")
        assert (topology.get("TopologyType"), topology.get("NumberOfElements")) == ("Polyvertex", str(n))
        assert grid.find("Geometry").get("GeometryType") == "XY"
        points = evaluate(grid.find("Geometry/DataItem"), reader).reshape(n, 2)
        assert np.array_equal(points, truth["frames/position"][k])
        attributes = {a.get("Name"): a for a in grid.findall("Attribute")}
        for name in ("radius", "mass"):
            assert attributes[name].get("AttributeType") == "Scalar"
            assert np.array_equal(evaluate(attributes[name].find("DataItem"), reader), truth["particles/" + name])
        for c, name in enumerate(("velocity_x", "velocity_y")):
            assert attributes[name].get("AttributeType") == "Scalar"
            component = evaluate(attributes[name].find("DataItem"), reader).reshape(n)
            assert np.array_equal(component, truth["frames/velocity"][k][:, c])
    for f in reader.hdf5_files.values():
        f.close()


def test_xdmf_names_the_run_file_relative_to_itself(run_file, run_collide, tmp_path):
    run, _ = run_file
    (tmp_path / "views").mkdir()
    xdmf = tmp_path / "views" / "run.xdmf"
    assert run_collide("export", run, "--out", xdmf).returncode == 0
    leaf = ET.parse(xdmf).getroot().find(".//DataItem[@Format='HDF']").text
    assert (xdmf.parent / leaf.split(":")[0]).resolve() == run.resolve()


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
    for name in ("run.xdmf", "run.xyz"):
        cli = exported(run_collide, run, name)
        ours = run.parent / ("python-" + name)  # the same folder: the XDMF names run.h5 alike
        assert collide.export(run, ours) == str(ours)
        assert ours.read_bytes() == cli.read_bytes()
    ours = run.parent / "python.gsd"
    collide.export(run, ours)
    hoomd = pytest.importorskip("gsd.hoomd")
    with hoomd.open(str(ours), "rb") as trajectory:
        assert [f.log["collide/time"][0] for f in trajectory] == list(truth["frames/time"])
