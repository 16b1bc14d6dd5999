"""Shared by the tests of the exports, --set and validate's defaults: the built `collide`
program (COLLIDE_EXE, set by ctest), the source tree, and running the program."""

import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]
SCENES = SOURCE / "data" / "scenes"


@pytest.fixture(scope="session")
def collide_exe():
    exe = os.environ.get("COLLIDE_EXE")
    if not exe:
        pytest.fail("COLLIDE_EXE is not set: run these tests through ctest")
    return exe


@pytest.fixture(scope="session")
def run_collide(collide_exe):
    def run(*args, cwd=None):
        return subprocess.run([collide_exe, *map(str, args)], capture_output=True, text=True, cwd=cwd,
                              stdin=subprocess.DEVNULL)
    return run
