#!/usr/bin/env python3
"""The course's lab bench: prints the numbers the exercises ask about from a run file.

    python3 docs/course/lab.py velocities RUN.h5... final velocity of every disk (needs --frames)
    python3 docs/course/lab.py counters RUN.h5...   steps, contacts and the solver's counters (and an
                                                    event solver's cell crossings per collision)
    python3 docs/course/lab.py energy RUN.h5...     kinetic energy drift and its largest jump
    python3 docs/course/lab.py error RUN.h5 REF.h5  largest position difference at the last frame
    python3 docs/course/lab.py same RUN.h5 OTHER.h5 whether the final states are bitwise identical
    python3 docs/course/lab.py settings RUN.h5...   the backend's recorded settings (provenance)
    python3 docs/course/lab.py checks SUMMARY.json SCENE BACKEND   one case group's checks
    python3 docs/course/lab.py sweep SUMMARY.json SCENE BACKEND    its error at each dt
    python3 docs/course/lab.py structure RUN.h5 [--from T|data]   g(d) with its batch-means error, Z by
                                        the contact route and by the collision virial, and the
                                        mean |psi6|, from the frames at t >= T, or (data) from
                                        the cut the run's |psi6| series chooses (chapter 4.4)
                                        (collide's module: collide.pair_correlation,
                                        collide.psi6; needs --frames)
    python3 docs/course/lab.py equilibration SCENE.toml [--duration T]   runs the scene on
                                        `event` through collide's module and prints its beta P d^2
                                        in 1000 windows cut from the data: each candidate start,
                                        its effective samples, the one chosen, and the means
                                        (collide.stationary_mean, the run record's estimate)
    python3 docs/course/lab.py check EXERCISE FILE.py  checks the code a student wrote for a
                                        coding exercise (galperin, root, haff, tunnel, blocks,
                                        metropolis, counting_sort, event_loop: this one runs
                                        `collide validate`, gofr, green_kubo); exit status 0
                                        when it is right

Each reads the HDF5 layout of docs/output-format.md with h5py, except `equilibration`, which runs
collide's module; the structure (g(r), psi6) and the statistics are collide's own, from the
module beside the program on PATH.
"""
import argparse
import json
import pathlib
import sys

import h5py
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import lab_check  # noqa: E402  (the coding exercises' checkers)


def velocities(run):
    with h5py.File(run, "r") as f:
        if "frames" not in f:
            sys.exit(f"{run}: written without --frames: rerun `collide run ... --frames`")
        t = f["frames/time"][-1]
        v = f["frames/velocity"][-1]
        m = f["particles/mass"][:]
    print(f"t = {t:g}")
    for i, (vx, vy) in enumerate(v):
        print(f"disk {i}: mass {m[i]:g}  v = ({vx:+.6f}, {vy:+.6f})  |v| = {np.hypot(vx, vy):.6f}")


def counters(run):
    with h5py.File(run, "r") as f:
        stats = f["stats"]
        print(f"steps {int(stats.attrs['steps'])}")
        print(f"contacts {int(stats.attrs['contacts'])}")
        counted = stats["counters"].attrs
        for name, value in sorted(counted.items()):
            print(f"{name} {float(value):.6g}")
        if "events_cell" in counted and counted["events_pair"] > 0:  # (the event solvers')
            print(f"cell crossings per collision {float(counted['events_cell'] / counted['events_pair']):.3g}")


def energy(run):
    with h5py.File(run, "r") as f:
        t = f["metrics/time"][:]
        k = f["metrics/kinetic_energy"][:] + f["metrics/potential_energy"][:]
    rel = (k - k[0]) / k[0]
    jumps = np.diff(rel)
    worst = int(np.argmax(np.abs(jumps)))
    print(f"relative energy change {rel[-1]:+.3e} over t = {t[0]:g} .. {t[-1]:g}")
    print(f"largest jump {jumps[worst]:+.3e} between t = {t[worst]:g} and {t[worst + 1]:g}")


def error(run, ref):
    with h5py.File(run, "r") as a, h5py.File(ref, "r") as b:
        xa, xb = a["frames/position"][-1], b["frames/position"][-1]
    print(f"max position error {np.max(np.linalg.norm(xa - xb, axis=1)):.3e}")


def same(run, other):
    with h5py.File(run, "r") as a, h5py.File(other, "r") as b:
        equal = all(np.array_equal(a[k][-1], b[k][-1]) for k in ("frames/position", "frames/velocity"))
    print("final states bitwise identical" if equal else "final states differ")


def settings(run):
    with h5py.File(run, "r") as f:
        for key, value in sorted(f.attrs.items()):
            if key == "backend" or key.startswith("backend_"):
                print(f"{key} = {value}")


def checks(summary, scene, backend):
    for c in json.load(open(summary))["checks"]:
        if c["scene"] == scene and c["backend"] == backend and c["subject"].endswith("seed1"):
            line = f"{c['check']}: {c['status']}"
            if c["status"] != "left_out":
                line += f" {c['value']:.3e} {c['comparison']} {c['tolerance']:.3e}"
            print(line + (f" ({c['detail']})" if c["detail"] else ""))


def sweep(summary, scene, backend):
    for line in json.load(open(summary))["work_precision"]:
        if line["scene"] == scene and line["backend"] == backend:
            for p in line["points"]:
                print(f"dt {p['dt']:g}: error {p['error']:.3e} +- {p['error_standard_error']:.3e} "
                      f"({p['replicates']} replicates)")


def start_time(text):
    """--from: a time, or "data" for the cut chosen from the run's own series."""
    if text == "data":
        return text
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"--from {text}: a time or 'data'") from None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("what", choices=["velocities", "counters", "energy", "error", "same", "settings",
                                         "checks", "sweep", "check", "structure", "equilibration"])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--from", dest="start", type=start_time, default=0.0,
                        help="structure: use the frames from this time on (after the melt), or from "
                             "the cut the run's |psi6| series chooses: --from data (chapter 4.4)")
    parser.add_argument("--duration", type=float, default=None,
                        help="equilibration: run this long instead of the scene's duration")
    args = parser.parse_args()
    if args.what == "equilibration":
        import lab_equilibration
        for path in args.files:
            lab_equilibration.equilibration(path, args.duration)
        return
    if args.what == "structure":
        import lab_structure
        for path in args.files:
            lab_structure.structure(path, args.start)
        return
    if args.what == "check":
        if len(args.files) != 2:
            parser.error(f"check needs EXERCISE FILE.py (exercises: {', '.join(lab_check.EXERCISES)})")
        sys.exit(lab_check.check(*args.files))
    pairs = {"error": error, "same": same}
    if args.what in pairs:
        if len(args.files) != 2:
            parser.error(f"{args.what} needs two run files")
        pairs[args.what](*args.files)
        return
    if args.what in ("checks", "sweep"):
        if len(args.files) != 3:
            parser.error(f"{args.what} needs SUMMARY.json SCENE BACKEND")
        {"checks": checks, "sweep": sweep}[args.what](*args.files)
        return
    for path in args.files:
        if len(args.files) > 1:
            print(f"== {path}")
        {"velocities": velocities, "counters": counters, "energy": energy, "settings": settings}[args.what](path)


if __name__ == "__main__":
    main()
