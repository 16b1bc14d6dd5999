"""The collide program, for the part of the report it draws itself (`collide render` for motion
strips): never a second implementation here. (The energy jumps come explained from `collide
report` itself, in energy_jumps.json.)"""
import os
import shutil
import subprocess


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
