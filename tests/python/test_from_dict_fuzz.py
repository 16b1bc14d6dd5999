# Scene.from_dict over a few thousand random dicts (tests/python/from_dict_cases.py, fixed
# seed): every case either builds a scene or raises ValueError or TypeError that names the key
# (SceneError, the scene reader's, names file, line and key). The cases run in child processes,
# a batch each, so that a crash fails this test, naming the case, instead of killing pytest.
import json
import pathlib
import subprocess
import sys

import pytest

SEED = 31
BATCHES = 4
PER_BATCH = 750
HERE = pathlib.Path(__file__).resolve().parent


def run_batch(batch):
    first = batch * PER_BATCH
    done = subprocess.run([sys.executable, str(HERE / "from_dict_cases.py"), str(SEED), str(first), str(PER_BATCH)],
                          capture_output=True, text=True, timeout=120)
    lines = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    started = [line["start"] for line in lines if "start" in line]
    assert done.returncode == 0, "case %s ended the interpreter with %d: %s" % (
        started[-1] if started else "?", done.returncode, done.stderr[-2000:])
    return [line for line in lines if "outcome" in line]


@pytest.mark.parametrize("batch", range(BATCHES))
def test_from_dict_builds_or_raises_naming_the_key(batch):
    results = run_batch(batch)
    assert len(results) == PER_BATCH
    for r in results:
        assert r["outcome"] in ("built", "SceneError", "ValueError", "TypeError"), r
        assert r["outcome"] == "built" or r["named"], r
    # The generator must reach every kind of outcome, or it tests less than it claims.
    outcomes = {r["outcome"] for r in results}
    assert {"built", "SceneError", "ValueError", "TypeError"} <= outcomes, outcomes
