"""The collide program, for the parts of the report it draws or computes itself (`collide render`
for motion strips, `collide explain` for energy jumps): never a second implementation here."""
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


def run_collide(args, timeout=300):
    """Runs `collide ARGS`; returns (stdout, None) or (None, why it failed in one line)."""
    program = collide_program()
    if program is None:
        return None, "no collide program was found (set COLLIDE_EXECUTABLE)"
    try:
        done = subprocess.run([program, *args], capture_output=True, text=True, timeout=timeout)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, str(e)
    if done.returncode != 0:
        lines = (done.stderr or done.stdout).strip().splitlines()
        return None, lines[-1] if lines else f"exit status {done.returncode}"
    return done.stdout, None
