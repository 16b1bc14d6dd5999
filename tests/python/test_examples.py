# The worked examples of docs/python.md run as written: each checks its own physics (exit
# status 0: the histogram matches Maxwell-Boltzmann, the pressures match Henderson's equation of
# state) and writes its figure.
import os
import subprocess
import sys

import pytest


@pytest.mark.parametrize("name", ["maxwell_boltzmann", "pressure_eos"])
def test_example_runs_and_draws(tmp_path, root, name):
    script = root / "docs" / "examples" / (name + ".py")
    run = subprocess.run([sys.executable, str(script), "--out", str(tmp_path)], capture_output=True, text=True,
                         timeout=300, env=dict(os.environ, MPLBACKEND="Agg"))
    assert run.returncode == 0, run.stdout + run.stderr
    png = tmp_path / (name + ".png")
    assert png.exists() and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
