"""collide: 2D hard-disk collisions from Python.

The solvers, the scene reader, the run driver and the suite runner are the C++ code of the
`collide` program (this package binds them; it computes no physics of its own). docs/python.md
describes the API; the short version:

    scene = collide.Scene.from_file("data/scenes/box_gas_1000.toml")
    sim = collide.Simulation(scene, backend="event")
    sim.advance_to(1.0)
    sim.positions, sim.velocities, sim.metrics(), sim.stats()

    result = collide.run(scene, "step", out="run.h5")   # metric series as NumPy arrays
    summary = collide.validate("validation/suites/default.toml", "results")

    faster = scene.with_overrides({"run.dt": 2.5e-4})      # as `collide run --set run.dt=2.5e-4`
    collide.run(scene, "step", out="run.h5", frames=True)
    collide.export("run.h5", "run.xdmf")                  # ParaView; also .gsd (OVITO), .xyz (ASE)
"""

import json
import os
import sys

from ._collide import (  # noqa: F401  (re-exported)
    Scene,
    SceneError,
    PSI6_CUTOFF_DIAMETERS,
    Simulation,
    SuiteError,
    backends,
    build_provenance,
    integrated_autocorrelation_time,
    local_psi6,
    pair_correlation,
    psi6,
    refusal,
    stationary_mean,
    toml_from_dict,
)
from . import _collide, safe_output

__version__ = build_provenance().get("collide_version", "")

__all__ = ["Scene", "SceneError", "Simulation", "SuiteError", "RunResult", "run", "read_run", "validate", "export",
           "backends", "build_provenance", "refusal", "toml_from_dict", "pair_correlation", "local_psi6", "psi6",
           "PSI6_CUTOFF_DIAMETERS", "stationary_mean", "integrated_autocorrelation_time"]


class RunResult(dict):
    """What `run` returns: a dict with

    metrics      name -> NumPy array, one entry per output time (time, kinetic_energy,
                 momentum_x, ..., the fields of docs/output-format.md's /metrics group)
    positions, velocities    the final state, (N, 2) float64
    state_hash   the 64-bit hash of the final state's bits
    stats        steps, contacts, phase_seconds, counters (as Simulation.stats())
    wall_seconds time spent inside the solver
    backend      the backend's name; out: the HDF5 file written, or None

    `result["kinetic_energy"]` is a shortcut for `result["metrics"]["kinetic_energy"]`.
    """

    def __missing__(self, key):
        return self["metrics"][key]


def _scene(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, dict):
        return Scene.from_dict(scene)
    if isinstance(scene, (str, os.PathLike)):
        return Scene.from_file(os.fspath(scene))
    raise TypeError("scene: expected a collide.Scene, a dict or a path, not %s" % type(scene).__name__)


def run(scene, backend="event", out=None, frames=False, progress=True, **options):
    """Runs `scene` (a Scene, dict or path) on `backend` through its output times, exactly as
    `collide run` does, and returns a RunResult. With `out`, writes the same HDF5 file as
    `collide run --out` (with `frames`, positions and velocities at every output time).
    `options` are the backend's: threads, real ("float"/"double"), device, or backend-specific.
    Ctrl-C stops at the next output time with KeyboardInterrupt; no file is then written."""
    if frames and out is None:
        raise ValueError("frames=True needs out= (frames are written to the HDF5 file)")
    result = RunResult(_collide._run(_scene(scene), backend, os.fspath(out) if out is not None else "",
                                     bool(frames), bool(progress), **options))
    result["out"] = os.fspath(out) if out is not None else None
    return result


def read_run(path, frames=False):
    """Reads a run file (`collide run --out`, `run(out=...)`) through the same checked reader as
    `collide render` and `collide report` (checksums, shapes, types, values; a damaged file
    raises naming the file and the dataset). Returns a dict with

    metrics      name -> NumPy array, one per column of docs/output-format.md's /metrics
                 (int64 for the counts), and total_energy
    particles    radius, mass, inv_mass
    stats        steps, contacts, phase_seconds and counters (/stats), as Simulation.stats()
    attributes   the root attributes: provenance, scene_text, seed, ...
    has_frames   whether the file holds frames
    With `frames=True` also frame_times (T,), positions and velocities (T, N, 2)."""
    return _collide._read_run(os.fspath(path), bool(frames))


def _class_file(name, solver):
    """The .py file that defines the class `solver`, or None (a built-in class, one made in an
    extension or at the prompt). inspect alone calls a class whose module is not in sys.modules
    (never imported, or removed since) "a built-in class": that case is named for what it is."""
    import inspect
    if solver.__module__ not in sys.modules:
        raise ValueError("solvers[%r]: %r comes from the module %r, which is not in sys.modules (not imported, or "
                         "removed since), so its file cannot be found; import the module, or give the solver as "
                         "\"path/file.py:%s\"" % (name, solver, solver.__module__, solver.__qualname__))
    try:
        return inspect.getsourcefile(solver)
    except TypeError:  # a built-in class, or one whose module has no file
        return None


_SOLVER_KEYS = ("command", "python", "rule", "exact", "precision", "long_lived")


def _solver_entry(name, solver):
    """(name, command, "file.py:Class", rule, exact, precision, long_lived) for one entry of
    validate(solvers=...). A class's own attributes (exact, precision, rule) are read by collide
    itself, as for `collide validate --python-solver` (solver_runner.py --declarations), not here.
    A dict's keys are those of a suite's [solver.NAME] table; a key it does not know is refused,
    not ignored (a misspelt "long-lived" would otherwise start the program once per call)."""
    if isinstance(solver, type):
        path = _class_file(name, solver)
        if path is None or "." in solver.__qualname__:
            raise ValueError("solvers[%r]: %r must be a class defined at the top level of a .py file, so that "
                             "collide's runner can load it in a process of its own" % (name, solver))
        return (name, "", "%s:%s" % (os.path.abspath(path), solver.__qualname__), "", False, "", False)
    if isinstance(solver, str) and ":" in solver and " " not in solver:
        return (name, "", solver, "", False, "", False)
    if isinstance(solver, dict):
        unknown = sorted(str(k) for k in solver if k not in _SOLVER_KEYS)
        if unknown:
            raise ValueError("solvers[%r]: no such key %s (allowed: %s)" % (name, ", ".join(map(repr, unknown)),
                                                                           ", ".join(_SOLVER_KEYS)))
        return (name, solver.get("command", ""), solver.get("python", ""), solver.get("rule", ""),
                bool(solver.get("exact", False)), solver.get("precision", ""), bool(solver.get("long_lived", False)))
    raise ValueError("solvers[%r]: expected a class, \"module:Class\", or a dict with \"command\" or \"python\" "
                     "(and optionally \"rule\", \"exact\", \"precision\", \"long_lived\")" % name)


def validate(suite, out="results", jobs=None, resume=False, solvers=None):
    """Runs a validation suite as `collide validate SUITE --out OUT` does (progress on stderr,
    the same summary on stdout) and returns summary.json as a dict. `jobs`: cases at the same
    time (default: one per core). Failed checks do not raise: look at summary["checks"] (or the
    counts printed).

    `solvers`: outside solvers that join the suite's backends for this run, name -> a class
    (its attributes declare what it claims: `exact = True`, `precision = "float"`, or `rule`,
    e.g. "collide-first", the stepping rule it implements), "module:Class", or {"command": "..."}
    for any program, with optional "rule", "exact", "precision" and "long_lived" (True: the
    program serves many calls, started once per worker as `COMMAND --serve`, as
    `--solver-long-lived`), the keys of a suite's [solver.NAME] table (docs/your-solver.md)."""
    entries = [_solver_entry(name, s) for name, s in (solvers or {}).items()]
    runner = os.path.join(os.path.dirname(os.path.abspath(__file__)), "solver_runner.py")
    counts = _collide._validate(os.fspath(suite), os.fspath(out), int(jobs or 0), bool(resume), entries,
                                sys.executable, runner)
    print("suite     %s: %d cases (%d run, %d resumed) in %.1f s, %d at a time" % (
        counts["suite"], counts["cases"], counts["cases_run"], counts["cases_resumed"], counts["wall_seconds"],
        counts["jobs"]))
    print("checks    %d passed, %d failed, %d left out" % (counts["passed"], counts["failed"], counts["left_out"]))
    with safe_output.open_input(os.path.join(os.fspath(out), "summary.json"), "r", encoding="utf-8") as f:
        summary = json.load(f)
    for c in summary.get("checks", []):
        if c.get("status") == "fail":
            print("FAIL      %s: %s: %s" % (c.get("subject"), c.get("check"), c.get("detail")))
    print("output    %s/summary.json, %s/junit.xml" % (out, out))
    sys.stdout.flush()
    return summary


def export(run, out, format=None):
    """Writes the frames of a run file (written with frames=True, or `collide run --frames`) as
    `collide export RUN --out OUT [--format F]` does: "xdmf" (ParaView, VisIt, meshio; its data in
    NAME.frames.h5 beside it), "gsd" (OVITO, freud, HOOMD; needs the gsd package) or "xyz" (extended XYZ: ASE,
    OVITO). Without `format`, the extension of `out` says which. docs/exporting.md."""
    run, out = os.fspath(run), os.fspath(out)
    if format is None:
        format = os.path.splitext(out)[1].lstrip(".").replace("xmf", "xdmf")
    if format == "gsd":
        from . import gsd_export
        _collide._check_export(run, out)  # the output path and every frame, as `collide export` does
        gsd_export.write_gsd(run, out)
    else:
        _collide._export(run, out, format or "")
    return out
