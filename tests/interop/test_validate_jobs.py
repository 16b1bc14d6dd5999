"""`collide validate` without --jobs runs one case per core and says so; --jobs still rules."""

import os

from conftest import SCENES


def suite_file(tmp_path):
    suite = tmp_path / "suite.toml"
    suite.write_text('name = "jobs"\nbackends = ["event", "step"]\nreference = "event"\nseeds = [1, 2, 3]\n'
                     'scene_dir = "%s"\n\n[[scene]]\nname = "head_on_equal"\nduration = 0.5\ndt = [1e-3]\n' % SCENES)
    return suite


def test_every_core_by_default(run_collide, tmp_path):
    cores = os.cpu_count()
    r = run_collide("validate", suite_file(tmp_path), "--out", tmp_path / "out")
    assert r.returncode == 0, r.stdout + r.stderr
    assert ", %d at a time" % cores in r.stdout, r.stdout
    assert "running 6 cases, %d at a time (--jobs %d)" % (min(cores, 6), cores) in r.stderr, r.stderr


def test_jobs_still_rules(run_collide, tmp_path):
    r = run_collide("validate", suite_file(tmp_path), "--out", tmp_path / "out", "--jobs", "1")
    assert r.returncode == 0, r.stdout + r.stderr
    assert ", 1 at a time" in r.stdout and "running 6 cases, 1 at a time (--jobs 1)" in r.stderr
