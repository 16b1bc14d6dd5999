"""The collide program, for the part of the report it draws itself (`collide render` for motion
strips): never a second implementation here. (The energy jumps come explained from `collide
validate`, in summary.json: the report runs no solver.) And its Python module, for the scripts that read run
files (docs/figures/make_figures.py, box2d/measure_presets.py): collide.read_run, the same
checked reader as every command (core/io/run_reader.h)."""
import os
import pathlib
import shutil
import sys


def collide_program():
    """$COLLIDE_EXECUTABLE (`collide report` sets it to itself), else the program that started
    this script, else `collide` on PATH; None when there is none."""
    explicit = os.environ.get("COLLIDE_EXECUTABLE")
    if explicit:
        return explicit
    try:
        parent = os.readlink(f"/proc/{os.getppid()}/exe")
        if os.path.basename(parent) == "collide":
            return parent
    except OSError:
        pass
    return shutil.which("collide")


def collide_module(program):
    """The Python module `collide` built beside `program` (build/<preset>/python; docs/python.md),
    or the one already on the path (an installed package)."""
    sys.path.insert(0, str(pathlib.Path(program).resolve().parent / "python"))
    import collide
    return collide
