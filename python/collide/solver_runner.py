"""Runs a Python solver class through collide's outside-solver protocol (docs/your-solver.md).

    python3 solver_runner.py MODULE:CLASS REQUEST_DIR

collide runs this for a solver given as a Python class (`[solver.NAME] python = "..."` in a
suite file, `collide validate --python-solver`, or `collide.validate(solvers=...)`). MODULE is
a module name importable from the current directory or sys.path, or the path of a .py file.
The class is created without arguments and used as

    solver.load(scene, initial)   scene: the request as a dict (numbers as float or int, "toml":
                                  the scene file's text); initial: NumPy arrays "positions" and
                                  "velocities" (N, 2), "radius", "mass" (N,), "stone" (N,) bool
    solver.advance_to(t)          t: absolute time, increasing
    solver.positions, solver.velocities     NumPy arrays, (N, 2) float64, attributes or
                                  properties: exactly that (nothing is broadcast or cast)
    solver.stats()                optional: {"steps": int, "contacts": int}
    solver.version                optional: a version string for the provenance
    solver.refuses(scene)         optional: a reason (str) not to run the scene, or None

What the class declares about itself, as class attributes (docs/your-solver.md, "Declaring an
exact solver"): `exact = True` (event-driven: no time step), `precision = "float"` (default
"double"), `rule = "collide-first"` or `"integrate-first"` (a stepped solver). collide reads
them once, before the run, with

    python3 solver_runner.py --declarations MODULE:CLASS OUT_FILE

which writes one "key value" line per attribute the class has (declarations()).

Only the standard library and NumPy: it needs no part of collide, so any Python with NumPy
runs it. read_request() and write_result() are the protocol for a program of your own.
"""

import importlib
import importlib.util
import io
import os
import sys

import numpy as np

try:  # imported as collide.solver_runner
    from . import safe_output
except ImportError:  # run as a script: its own folder is on sys.path
    import safe_output

# request.txt keys whose values are words, not numbers; output_times is a list.
_WORDS = {"solver", "scene", "order", "boundary"}


def read_request(directory):
    """request.txt as a dict, initial.npy as the arrays of `initial` (see the module docstring)."""
    scene = {}
    with open(os.path.join(directory, "request.txt"), encoding="utf-8") as f:
        for line in f:
            key, _, value = line.strip().partition(" ")
            if not key:
                continue
            if key == "output_times":
                scene[key] = [float(v) for v in value.split()]
            elif key == "option":  # protocol 2: a suite variant's setting, "option KEY VALUE"
                name, _, setting = value.partition(" ")
                scene.setdefault("options", {})[name] = setting
            elif key in _WORDS:
                scene[key] = value
            elif key in ("protocol", "seed", "disks", "substeps"):
                scene[key] = int(value)
            else:
                scene[key] = float(value)
    with open(os.path.join(directory, "scene.toml"), encoding="utf-8") as f:
        scene["toml"] = f.read()
    table = np.load(os.path.join(directory, "initial.npy"))
    initial = {
        "positions": table[:, 0:2].copy(),
        "velocities": table[:, 2:4].copy(),
        "radius": table[:, 4].copy(),
        "mass": table[:, 5].copy(),
        "stone": table[:, 6] != 0,
    }
    return scene, initial


def write_result(directory, times, states, steps=None, contacts=None, version=None, refuse=None, precision=None):
    """states.npy ((K, N, 4) float64: x, y, vx, vy at each of the K times) and result.txt.
    `precision` ("double" or "float"), when given, must be the one the solver is declared with."""
    lines = []
    if refuse is not None:
        lines.append("refuse " + " ".join(str(refuse).split()))
    else:
        answer = io.BytesIO()
        np.save(answer, np.ascontiguousarray(states, dtype="<f8"))
        safe_output.write_bytes(os.path.join(directory, "states.npy"), answer.getvalue())  # the output guard
        lines.append("times " + " ".join(repr(float(t)) for t in times))
        if steps is not None:
            lines.append("steps %d" % int(steps))
        if contacts is not None:
            lines.append("contacts %d" % int(contacts))
        if precision:
            lines.append("precision %s" % precision)
    if version:
        lines.append("version " + " ".join(str(version).split()))
    safe_output.write_text(os.path.join(directory, "result.txt"), "\n".join(lines) + "\n")


def load_class(spec):
    """The class that "module:Class" or "path/file.py:Class" names."""
    module_name, _, class_name = spec.rpartition(":")
    if not module_name or not class_name:
        raise SystemExit("solver_runner: expected MODULE:CLASS, not %r" % spec)
    if module_name.endswith(".py"):
        path = os.path.abspath(module_name)
        name = "collide_solver_" + os.path.splitext(os.path.basename(path))[0]
        module_spec = importlib.util.spec_from_file_location(name, path)
        if module_spec is None or not os.path.isfile(path):
            raise SystemExit("solver_runner: no such file %s" % path)
        sys.path.insert(0, os.path.dirname(path))   # its sibling modules import as from a script
        module = importlib.util.module_from_spec(module_spec)
        sys.modules[name] = module
        module_spec.loader.exec_module(module)
    else:
        sys.path.insert(0, os.getcwd())
        module = importlib.import_module(module_name)
    try:
        return getattr(module, class_name)
    except AttributeError:
        raise SystemExit("solver_runner: module %s has no class %s" % (module_name, class_name))


def checked_pairs(solver, name, disks, t):
    """solver.<name> after advance_to(t), refused unless it is exactly what the module docstring
    asks for: a NumPy array of shape (N, 2) and dtype float64 (either byte order). Nothing is
    broadcast or cast (a (1, 2) row, an int, str or complex array, a list, None), as collide
    refuses a program's states.npy of another shape or dtype (external/external_solver.cpp)."""
    where = "solver_runner: %s.%s at t = %r" % (type(solver).__name__, name, t)
    expected = "expected a NumPy array of shape (%d, 2) (disks, [x, y]) and dtype float64" % disks
    if not hasattr(solver, name):
        raise SystemExit("%s: there is no such attribute; %s" % (where, expected))
    value = getattr(solver, name)
    if not isinstance(value, np.ndarray):
        raise SystemExit("%s is %s, %s" % (where, "None" if value is None else "a " + type(value).__name__, expected))
    if value.shape != (disks, 2):
        raise SystemExit("%s has shape %s, %s" % (where, value.shape, expected))
    if value.dtype.kind != "f" or value.dtype.itemsize != 8:
        raise SystemExit("%s has dtype %s, %s" % (where, value.dtype, expected))
    return value


# The class attributes that declare what a solver claims, and how each is written.
_DECLARATIONS = {"exact": lambda v: "true" if v else "false", "precision": str, "rule": str}


def declarations(cls):
    """The "key value" lines of what `cls` declares as attributes (exact, precision, rule)."""
    lines = []
    for key, text in _DECLARATIONS.items():
        value = getattr(cls, key, None)
        if value is not None and value != "":
            lines.append("%s %s" % (key, text(value)))
    return lines


def run(spec, directory):
    scene, initial = read_request(directory)
    solver = load_class(spec)()
    version = getattr(solver, "version", None)
    refuses = getattr(solver, "refuses", None)
    reason = refuses(scene) if refuses else None
    if reason:
        write_result(directory, [], None, version=version, refuse=reason)
        return
    solver.load(scene, initial)
    times = scene["output_times"]
    disks = len(initial["radius"])
    states = np.empty((len(times), disks, 4))
    for k, t in enumerate(times):
        solver.advance_to(t)
        states[k, :, 0:2] = checked_pairs(solver, "positions", disks, t)
        states[k, :, 2:4] = checked_pairs(solver, "velocities", disks, t)
    stats = solver.stats() if hasattr(solver, "stats") else {}
    write_result(directory, times, states, steps=stats.get("steps"), contacts=stats.get("contacts"), version=version,
                 precision=getattr(solver, "precision", None))


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--declarations":
        with open(sys.argv[3], "w", encoding="utf-8") as f:
            f.write("".join(line + "\n" for line in declarations(load_class(sys.argv[2]))))
    elif len(sys.argv) == 3:
        run(sys.argv[1], sys.argv[2])
    else:
        raise SystemExit("usage: solver_runner.py MODULE:CLASS REQUEST_DIR\n"
                         "       solver_runner.py --declarations MODULE:CLASS OUT_FILE")
