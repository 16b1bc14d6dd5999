"""`cmake --install` into a temporary prefix: the installed program finds its scene library,
runs a small suite and exports a run with the installed GSD writer; the installed Python package
imports from the prefix. (Needs the program and the Python module built: ctest after a build.)"""

import glob
import os
import pathlib
import subprocess
import sys

import pytest


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    prefix = tmp_path_factory.mktemp("prefix")
    r = subprocess.run([os.environ["CMAKE_COMMAND"], "--install", os.environ["COLLIDE_BUILD_DIR"], "--prefix", prefix],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    return prefix


def installed(prefix, *args, cwd=None):
    return subprocess.run([str(prefix / "bin" / "collide"), *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, stdin=subprocess.DEVNULL)


def test_the_layout(prefix):
    share = prefix / "share" / "collide"
    for path in ("data/scenes/head_on_equal.toml", "validation/suites/default.toml",
                 "validation/report/make_report.py", "python/collide/gsd_export.py"):
        assert (share / path).is_file(), path
    assert (prefix / "share" / "doc" / "collide" / "exporting.md").is_file()


def test_the_installed_program_runs_a_suite_and_exports(prefix, tmp_path):
    scenes = prefix / "share" / "collide" / "data" / "scenes"
    listing = installed(prefix, "scenes")
    assert listing.returncode == 0 and "head_on_equal.toml" in listing.stdout, listing.stderr
    suite = tmp_path / "suite.toml"
    suite.write_text('name = "installed"\nbackends = ["event", "step"]\nreference = "event"\nseeds = [1]\n'
                     'scene_dir = "%s"\n\n[[scene]]\nname = "head_on_equal"\nduration = 0.5\ndt = [1e-3]\n' % scenes)
    r = installed(prefix, "validate", suite, "--out", tmp_path / "out", cwd="/")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "checks    " in r.stdout and ", 0 failed" in r.stdout
    run = tmp_path / "run.h5"
    assert installed(prefix, "run", scenes / "head_on_equal.toml", "--frames", "--out", run).returncode == 0
    exported = installed(prefix, "export", run, "--out", tmp_path / "run.gsd", cwd="/")
    assert exported.returncode == 0, exported.stderr
    assert (tmp_path / "run.gsd").stat().st_size > 0


def test_the_installed_python_package_imports_from_the_prefix(prefix):
    if os.environ.get("COLLIDE_SANITIZE") == "ON":
        pytest.skip("an instrumented module needs the sanitizer runtimes preloaded")
    found = glob.glob(str(prefix / "**" / "collide" / "__init__.py"), recursive=True)
    assert len(found) == 1, found
    site = pathlib.Path(found[0]).parent.parent
    r = subprocess.run([sys.executable, "-c", "import collide, sys; print(collide.__file__); "
                        "print([b['name'] for b in collide.backends()])"],
                       capture_output=True, text=True, env={**os.environ, "PYTHONPATH": str(site)}, cwd="/")
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[0].startswith(str(prefix)) and "'event'" in r.stdout
