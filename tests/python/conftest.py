# Shared set-up of the pytest suite for the Python module (python/, docs/python.md). ctest runs
# it with PYTHONPATH pointing at <build>/python and COLLIDE_EXE at the `collide` program; run
# by hand: PYTHONPATH=build/release/python /usr/bin/python3 -m pytest tests/python
import json
import os
import pathlib
import subprocess
import sys
import textwrap

import pytest

import collide

ROOT = pathlib.Path(__file__).resolve().parents[2]

# A small gas every backend runs in well under a second: 120 disks at area fraction 0.21 in a
# reflecting box, 100 steps of dt = 1e-3 (the CLI comparisons and the piecewise runs).
SMALL_GAS = """description = "120 disks, small gas for the Python tests"
seed = 7

[world]
box = [0.0, 0.0, 15.0, 15.0]
boundary = "reflect"

[run]
duration = 0.1
output_interval = 0.02
dt = 1e-3

[[particles]]
kind = "gas"
count = 120
radius = 0.5
mass = 1.0
velocity = { maxwell = 1.0 }
"""


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def collide_exe():
    exe = os.environ.get("COLLIDE_EXE", str(ROOT / "build" / "release" / "collide"))
    if not os.path.exists(exe):
        pytest.skip("the collide program is not built: " + exe)
    return exe


@pytest.fixture()
def small_gas():
    return collide.Scene.from_toml(SMALL_GAS, "small_gas")


def backend_names():
    """The backends that can run SMALL_GAS (a walled box): a sampler of periodic boxes only is
    left out by its own declared reason (collide.refusal), not by name."""
    scene = collide.Scene.from_toml(SMALL_GAS, "small_gas")
    return [b["name"] for b in collide.backends() if collide.refusal(b["name"], scene) is None]


def in_child(code, timeout=60):
    """Runs `code` (which prints one JSON line) in a fresh interpreter; returns what it printed,
    or fails with how the child ended (a signal: a crash)."""
    try:
        done = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True,
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        pytest.fail("the call did not return within %d s" % timeout)
    assert done.returncode == 0, "child ended with %d: %s" % (done.returncode, done.stderr[-2000:])
    return json.loads(done.stdout.strip().splitlines()[-1])
