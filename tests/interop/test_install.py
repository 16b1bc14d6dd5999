"""`cmake --install` into a temporary prefix: the installed program finds its scene library,
runs a small suite and exports a run with the installed GSD writer; the installed Python package
imports from the prefix; a ten-line C++ program builds against find_package(collide) and gets
the kinetic energy the program gets. (Needs the build done: ctest after a build.)"""

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
                 "validation/report/make_report.py", "validation/report/templates/index.html.j2",
                 "python/collide/gsd_export.py",
                 "python/collide/solver_runner.py", "validation/report/compare.py",
                 "data/scenes/physics/hard_disk_fluid.toml", "data/references/kolafa_rottner_2006.toml"):
        assert (share / path).is_file(), path
    # The default suite's physics rows read their published references from ../../data/references.
    suites = share / "validation" / "suites"
    assert (suites / ".." / ".." / "data" / "references" / "galperin_2003.toml").resolve().is_file()
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


def test_the_installed_program_runs_a_python_solver_through_its_runner(prefix, tmp_path):
    scenes = prefix / "share" / "collide" / "data" / "scenes"
    stepper = pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples" / "solvers" / "numpy_stepper.py"
    suite = tmp_path / "suite.toml"
    suite.write_text('name = "installed"\nbackends = ["event"]\nwarmup_fraction = 0\nscene_dir = "%s"\n\n'
                     '[[scene]]\nname = "head_on_equal"\ncompare = "trajectory"\nduration = 0.5\ndt = [1e-3]\n' % scenes)
    r = installed(prefix, "validate", suite, "--out", tmp_path / "out", "--python-solver", "np=%s:NumPyStepper" % stepper,
                  cwd="/")
    assert r.returncode == 0, r.stdout + r.stderr
    assert installed(prefix, "compare", tmp_path / "out", tmp_path / "out").returncode == 0


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


CONSUMER_CMAKE = """cmake_minimum_required(VERSION 3.25)
project(uses_collide C CXX)   # C: the HDF5 the package links is found as a C library
set(CMAKE_CXX_STANDARD 20)
find_package(collide REQUIRED)
add_executable(final_energy main.cpp)
target_link_libraries(final_energy PRIVATE collide::reference)
"""

CONSUMER_MAIN = """// The exact solver on a scene file, from a program of its own: the final kinetic energy.
#include <cstdio>
#include "core/metrics.h"
#include "core/scene/scene_loader.h"
#include "reference/event/event_solver.h"

int main(int, char** argv) {
    const collide::Scene scene = collide::load_scene(argv[1]);
    collide::EventSolver solver;
    solver.load(scene, collide::generate_initial_state(scene));
    solver.advance_to(scene.run.duration);
    collide::ParticleState<double> state;
    solver.read_state(state);
    std::printf("%.17g\\n", collide::compute_metrics(scene, state, solver.time()).kinetic_energy);
}
"""


def test_a_cpp_program_builds_against_the_installed_package(prefix, tmp_path):
    if os.environ.get("COLLIDE_SANITIZE") == "ON":
        pytest.skip("instrumented static libraries link only into an instrumented program")
    source, build = tmp_path / "source", tmp_path / "build"
    source.mkdir()
    (source / "CMakeLists.txt").write_text(CONSUMER_CMAKE)
    (source / "main.cpp").write_text(CONSUMER_MAIN)
    cmake = os.environ["CMAKE_COMMAND"]
    for command in ([cmake, "-S", source, "-B", build, "-DCMAKE_PREFIX_PATH=%s" % prefix, "-DCMAKE_BUILD_TYPE=Release"],
                    [cmake, "--build", build]):
        r = subprocess.run(command, capture_output=True, text=True)
        assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    scene = prefix / "share" / "collide" / "data" / "scenes" / "head_on_equal.toml"
    ours = subprocess.run([str(build / "final_energy"), str(scene)], capture_output=True, text=True)
    assert ours.returncode == 0, ours.stderr
    run = installed(prefix, "run", scene, "--backend", "event")
    line = next(l for l in run.stdout.splitlines() if l.startswith("energy"))
    # "energy    kinetic K0 -> K1 (relative change ...)", K1 printed with 15 digits
    assert line.split("-> ")[1].split(" ")[0] == "%.15g" % float(ours.stdout), (line, ours.stdout)
