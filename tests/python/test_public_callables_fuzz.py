# Every public callable of the package (functions, classes, their methods and properties; see
# hostile_calls.py) called with hostile values: strings of 10^5 characters, a NUL, dotted keys
# 150,000 parts deep, dicts 10^5 deep, huge ints, NaN, None, wrong types and uninitialised
# objects. Each target runs in a child process of its own, several at a time; exceptions are
# fine, but every child must reach its end: none may die by a signal (docs/python.md, "Hostile
# input").
import concurrent.futures
import os
import pathlib
import subprocess
import sys

import collide
from hostile_calls import public_callables

HERE = pathlib.Path(__file__).resolve().parent
CHILD_SECONDS = 120


def child_environment():
    """This environment, with the package this process imported first on the path (the
    children run in scratch directories, where a relative PYTHONPATH would find nothing)."""
    env = dict(os.environ)
    package_parent = str(pathlib.Path(collide.__file__).resolve().parents[1])
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [package_parent, env.get("PYTHONPATH")]))
    return env


def call_in_child(target, scratch):
    """None if the child ran every call and exited 0, else what happened and the call it was in."""
    scratch.mkdir()
    progress = scratch / "progress.txt"
    try:
        done = subprocess.run([sys.executable, str(HERE / "hostile_calls.py"), target, str(progress)], cwd=scratch,
                              env=child_environment(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                              timeout=CHILD_SECONDS)
        ended = "signal %d" % -done.returncode if done.returncode < 0 else "exit status %d" % done.returncode
        if done.returncode == 0:
            return None
    except subprocess.TimeoutExpired:
        ended, done = "no end within %d s" % CHILD_SECONDS, None
    last = progress.read_text(encoding="utf-8", errors="replace").splitlines()[-1:] if progress.exists() else []
    tail = done.stderr.decode(errors="replace")[-600:] if done is not None else ""
    return "%s: %s in %s\n%s" % (target, ended, last[0] if last else "(before the first call)", tail)


def test_the_fuzz_reaches_every_kind_of_callable():
    targets = public_callables()
    for name in ("collide.run", "collide.export", "collide.validate", "collide.read_run", "collide.Scene",
                 "collide.Scene.from_file", "collide.Scene.with_overrides", "collide.Scene.name",
                 "collide.Simulation", "collide.Simulation.time", "collide.Simulation.__len__",
                 "collide.Simulation.advance_to", "collide.solver_runner.run", "collide.gsd_export.write_gsd"):
        assert name in targets, name
    assert not any(t.split(".")[-1] in ("os", "np", "json", "sys") for t in targets), targets


def test_no_public_callable_dies_by_a_signal(tmp_path):
    targets = public_callables()
    workers = max(2, min(8, os.cpu_count() or 2))
    with concurrent.futures.ThreadPoolExecutor(workers) as pool:
        outcomes = list(pool.map(lambda i_t: call_in_child(i_t[1], tmp_path / str(i_t[0])), enumerate(targets)))
    failures = [o for o in outcomes if o is not None]
    assert not failures, "%d of %d targets died:\n\n%s" % (len(failures), len(targets), "\n\n".join(failures))
