"""A run file's frames as a GSD file in HOOMD's schema, for OVITO, freud and HOOMD
(docs/exporting.md). Run as a script by `collide export --format gsd`, imported by
`collide.export`; needs only h5py, numpy and gsd (Debian: python3-h5py, python3-numpy,
python3-gsd), not the collide extension. It is the one script that still reads run files with
h5py rather than collide.read_run: `collide export` runs it with the system interpreter, which
does not find the extension (it lies in the build tree, or under the install prefix's own
site-packages) and, in a sanitized build, could not load it without preloading the sanitizer
runtimes; the program checks every frame with its own reader (core/io/run_reader.h) first.

    python3 gsd_export.py RUN.h5 OUT.gsd

What the schema fixes, and how a run maps onto it:
  particles/position   float32 (N, 3): HOOMD's box is centred on the origin, so the centres are
                       shifted by the box's centre (log/collide/box_centre gives it back) and
                       rounded to float32; z = 0
  particles/velocity   float32 (N, 3), z = 0
  particles/diameter   float32: twice the radius
  particles/mass       float32
  particles/typeid     0 for a disk, 1 for a kinematic stone (types "disk", "stone")
  configuration/box    [Lx, Ly, 0, 0, 0, 0], dimensions 2
  configuration/step   the output's index k (HOOMD counts steps; a run's outputs are k * interval)
  log/collide/time     the simulation time, float64, exactly as in the run file
"""

import sys

import h5py
import numpy as np

try:  # imported as collide.gsd_export
    from . import safe_output
except ImportError:  # run as a script: its own folder is on sys.path
    import safe_output

try:
    import gsd.hoomd
except ImportError:  # named here, rather than as a traceback
    gsd = None

_Frame = None if gsd is None else getattr(gsd.hoomd, "Frame", None) or gsd.hoomd.Snapshot


def _box(run):
    """(xmin, ymin, xmax, ymax) from the scene text the run file carries."""
    import tomllib
    scene = tomllib.loads(run.attrs["scene_text"])
    return scene["world"]["box"]


def _frame(run, k, box, typeid):
    xmin, ymin, xmax, ymax = box
    centre = np.array([(xmin + xmax) / 2, (ymin + ymax) / 2])
    n = typeid.size
    frame = _Frame()
    frame.configuration.step = k
    frame.configuration.dimensions = 2
    frame.configuration.box = [xmax - xmin, ymax - ymin, 0, 0, 0, 0]
    frame.particles.N = n
    frame.particles.types = ["disk", "stone"]
    frame.particles.typeid = typeid
    position = np.zeros((n, 3))
    position[:, :2] = run["frames/position"][k] - centre
    velocity = np.zeros((n, 3))
    velocity[:, :2] = run["frames/velocity"][k]
    frame.particles.position = position.astype(np.float32)
    frame.particles.velocity = velocity.astype(np.float32)
    frame.particles.diameter = (2 * run["particles/radius"][:]).astype(np.float32)
    frame.particles.mass = run["particles/mass"][:].astype(np.float32)
    frame.log = {"collide/time": np.array([run["frames/time"][k]], dtype=np.float64),
                 "collide/box_centre": centre}
    return frame


def write_gsd(run_path, out_path):
    """Writes every frame of `run_path` to `out_path` (a temporary file beside it, renamed when
    complete: an existing file is replaced whole or not at all; safe_output.atomic_output)."""
    if gsd is None:
        raise RuntimeError("the Python package gsd is missing (Debian: apt-get install python3-gsd)")
    safe_output.check_input_file(run_path)  # h5py would wait on a FIFO for good
    with h5py.File(run_path, "r") as run:
        if "frames" not in run:
            raise RuntimeError("%s: the run has no frames to export: it was written without --frames; "
                               "rerun it with `collide run ... --frames`" % run_path)
        box = _box(run)
        typeid = (run["particles/inv_mass"][:] == 0).astype(np.uint32)
        # The output guard and atomic rename every writer of collide shares: a link is followed
        # (its file replaced, the link kept), and a FIFO or a device put at the path during the
        # export is refused, not replaced by a plain file.
        with safe_output.atomic_output(out_path) as temporary:
            with gsd.hoomd.open(temporary, "wb") as trajectory:
                for k in range(run["frames/time"].shape[0]):
                    trajectory.append(_frame(run, k, box, typeid))


def main(argv):
    if len(argv) != 3:
        print("usage: gsd_export.py RUN.h5 OUT.gsd", file=sys.stderr)
        return 2
    try:
        write_gsd(argv[1], argv[2])
    except (OSError, RuntimeError, KeyError, safe_output.OutputPathError) as e:
        print("collide: error: %s" % e, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
