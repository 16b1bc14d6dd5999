"""The engines of engines/ (docs/engines.md): each Node adapter, in each preset, answers the
protocol on a head-on collision; a missing package fails naming the engine and `npm ci`; and the
CI subset of the engines suite runs every engine through `collide validate` (protocol 2: option
lines for the presets, `seconds` as the cost, declared capabilities, package hashes in the
provenance). Never skipped: without Node or the packages these tests fail and say what to install."""

import json
import os
import pathlib
import shutil
import subprocess
import tomllib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
ENGINES_DIR = ROOT / "engines"
COLLIDE = os.environ.get("COLLIDE_EXE", str(ROOT / "build" / "release" / "collide"))
ENGINES = [e["name"] for e in json.loads((ENGINES_DIR / "engines.json").read_text())]


def write_request(directory, options=(), restitution=1.0, speed=1.0):
    """Two equal disks (radius 0.5) meeting head-on at x = 5 at t = 0.5, in a 10 x 4 box."""
    directory.mkdir(parents=True, exist_ok=True)
    lines = ["protocol 2", "solver test", "scene head_on", "seed 1", "disks 2", "start_time 0", "output_times 1 2",
             "dt 0.001", "substeps 1", "order collide-first", "boundary reflect", "xmin 0", "ymin 0", "xmax 10",
             "ymax 4", f"restitution {restitution}", "wall_restitution 1", "friction 0", "gravity_x 0",
             "gravity_y 0", "damping 0", "duration 2"] + [f"option {k} {v}" for k, v in options]
    (directory / "request.txt").write_text("\n".join(lines) + "\n")
    x = 0.5 + 0.5 * speed
    np.save(directory / "initial.npy", np.array([[5 - x, 2, speed, 0, 0.5, 1, 0], [5 + x, 2, -speed, 0, 0.5, 1, 0]], float))


def call(adapter, directory):
    return subprocess.run(["node", str(adapter), str(directory)], capture_output=True, text=True, timeout=120)


def result(directory):
    out = {}
    for line in (directory / "result.txt").read_text().splitlines():
        key, _, rest = line.partition(" ")
        out[key] = rest
    return out


def test_node_and_the_pinned_packages_are_installed():
    assert shutil.which("node"), "node not found: install Debian's nodejs and npm (scripts/install-deps.sh)"
    lock = json.loads((ENGINES_DIR / "package-lock.json").read_text())["packages"]
    for name, pinned in json.loads((ENGINES_DIR / "package.json").read_text())["dependencies"].items():
        manifest = ENGINES_DIR / "node_modules" / name / "package.json"
        assert manifest.exists(), f"{name} is not installed: run `npm ci` in {ENGINES_DIR} (scripts/install-deps.sh)"
        installed = json.loads(manifest.read_text())["version"]
        assert installed == pinned == lock[f"node_modules/{name}"]["version"], (name, installed, pinned)


@pytest.mark.parametrize("engine,preset", [(e, p) for e in ENGINES for p in ("tuned", "shipped")
                                           if (e, p) != ("matter", "shipped")])
def test_each_adapter_exchanges_velocities_head_on(tmp_path, engine, preset):
    # Equal masses, e = 1, relative speed 2 (above Rapier's and planck's restitution thresholds in
    # their shipped units; matter.js shipped is the next test): they swap velocities, and every
    # engine meets them at x = 4.5 and 5.5.
    write_request(tmp_path, [("preset", preset)])
    r = call(ENGINES_DIR / f"{engine}.js", tmp_path)
    assert r.returncode == 0, r.stderr
    answer = result(tmp_path)
    assert answer["times"].split() == ["1", "2"]
    assert int(answer["steps"]) == 2000 and int(answer["contacts"]) == 1
    assert float(answer["seconds"]) > 0
    assert f"(preset {preset})" in answer["version"]
    states = np.load(tmp_path / "states.npy")
    assert states.shape == (2, 2, 4) and states.dtype == np.float64
    np.testing.assert_allclose(states[1, :, 2], [-1.0, 1.0], atol=1e-5)
    np.testing.assert_allclose(states[1, :, 0], [3.0, 7.0], atol=2e-3)  # matter.js: a 64-gon's flat side


@pytest.mark.parametrize("engine", ENGINES)
def test_each_adapter_serves_many_requests_from_one_start(tmp_path, engine):
    # The long-lived mode (engines/protocol.js, docs/your-solver.md): one process answers request
    # after request read from stdin, each exactly as a one-shot call answers it (no world carried
    # over), replies "failed ..." to a request it cannot answer and goes on, and exits at end of file.
    write_request(tmp_path / "tuned", [("preset", "tuned")])
    write_request(tmp_path / "shipped", [("preset", "shipped")])
    write_request(tmp_path / "bad", [("velocity_thrshold", "0")])
    write_request(tmp_path / "again", [("preset", "tuned")])
    write_request(tmp_path / "oneshot", [("preset", "tuned")])
    requests = "".join(f"{tmp_path / name}\n" for name in ("tuned", "shipped", "bad", "again"))
    r = subprocess.run(["node", str(ENGINES_DIR / f"{engine}.js"), "--serve"], input=requests, capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    replies = r.stdout.splitlines()
    assert replies[:2] == ["done", "done"] and replies[3] == "done" and len(replies) == 4, r.stdout
    assert replies[2].startswith(f"failed {engine}: option velocity_thrshold: unknown"), replies[2]
    assert "(preset shipped)" in result(tmp_path / "shipped")["version"]
    assert call(ENGINES_DIR / f"{engine}.js", tmp_path / "oneshot").returncode == 0
    for served in ("tuned", "again"):  # bit for bit what a fresh process computes
        np.testing.assert_array_equal(np.load(tmp_path / served / "states.npy"), np.load(tmp_path / "oneshot" / "states.npy"))


def run_head_on(directory, engine, preset, speed):
    write_request(directory, [("preset", preset)], speed=speed)
    r = call(ENGINES_DIR / f"{engine}.js", directory)
    assert r.returncode == 0, r.stderr
    return np.load(directory / "states.npy")[1, :, 2]


def test_planck_shipped_velocity_threshold_stops_slow_collisions_that_tuned_bounces(tmp_path):
    # Relative speed 0.2 m/s, below planck's (Box2D's) velocityThreshold of 1 m/s at scale 1:
    # shipped solves for zero normal relative velocity (both stop); tuned exchanges velocities.
    np.testing.assert_allclose(run_head_on(tmp_path / "tuned", "planck", "tuned", 0.1), [-0.1, 0.1], atol=1e-6)
    np.testing.assert_allclose(run_head_on(tmp_path / "shipped", "planck", "shipped", 0.1), [0.0, 0.0], atol=1e-6)


def test_matter_shipped_resting_threshold_loses_most_of_a_head_on_bounce_that_tuned_keeps(tmp_path):
    # Scene units 1:1 are matter.js's pixels: relative speed 2 per second is 1/30 per base step,
    # below its resting threshold (2), so shipped does not bounce elastically; tuned does.
    np.testing.assert_allclose(run_head_on(tmp_path / "tuned", "matter", "tuned", 1.0), [-1.0, 1.0], atol=1e-5)
    shipped = run_head_on(tmp_path / "shipped", "matter", "shipped", 1.0)
    assert abs(shipped[1] - shipped[0]) < 1.0, shipped


def test_an_unknown_option_fails_naming_the_engine_and_the_key(tmp_path):
    write_request(tmp_path, [("velocity_thrshold", "0")])
    r = call(ENGINES_DIR / "planck.js", tmp_path)
    assert r.returncode != 0
    assert "planck" in r.stderr and "velocity_thrshold" in r.stderr and "velocity_threshold" in r.stderr


def test_a_missing_package_fails_naming_the_engine_and_npm_ci(tmp_path):
    # The adapters without node_modules, as in a clone before the set-up script.
    bare = tmp_path / "engines"
    bare.mkdir()
    for f in ["protocol.js", "engines.json", "rapier.js", "list.js"]:
        shutil.copy(ENGINES_DIR / f, bare / f)
    write_request(tmp_path / "req")
    r = call(bare / "rapier.js", tmp_path / "req")
    assert r.returncode == 3
    assert "rapier" in r.stderr and "@dimforge/rapier2d-compat" in r.stderr and "npm ci" in r.stderr
    listing = subprocess.run(["node", str(bare / "list.js")], capture_output=True, text=True).stdout
    assert "not installed: run `npm ci`" in listing


def test_collide_backends_lists_the_engines_with_their_versions():
    out = subprocess.run([COLLIDE, "backends"], capture_output=True, text=True, check=True).stdout
    assert "chipmunk" in out
    lock = json.loads((ENGINES_DIR / "package-lock.json").read_text())["packages"]
    for name in ["@dimforge/rapier2d-compat", "matter-js", "planck"]:
        assert f"{name} {lock['node_modules/' + name]['version']}" in out, out


@pytest.fixture(scope="module")
def ci_suite(tmp_path_factory):
    out = tmp_path_factory.mktemp("engines") / "out"
    r = subprocess.run([COLLIDE, "validate", str(ROOT / "tests" / "engines" / "engines_ci.toml"), "--out", str(out),
                        "--jobs", "2"], capture_output=True, text=True)
    return out, json.loads((out / "summary.json").read_text()), r


def test_every_engine_and_preset_completes_every_case_it_handles(ci_suite):
    out, summary, run = ci_suite
    for engine in ENGINES:
        for label in (engine, f"{engine}[shipped]"):
            cases = [c for c in summary["cases"] if c["backend"] == label]
            assert cases, (label, run.stderr[-2000:])
            ran = [c for c in cases if c["scene"] != "periodic_gas"]
            assert ran and all(c["status"] == "completed" for c in ran), [(c["id"], c["status"]) for c in ran]


def test_periodic_scenes_are_left_out_by_the_declaration_without_a_call(ci_suite):
    out, summary, _ = ci_suite
    for engine in ENGINES:
        case = next(c for c in summary["cases"] if c["backend"] == engine and c["scene"] == "periodic_gas")
        assert case["status"] == "left_out"
        assert "declares that it handles" in json.dumps(case) and "periodic" in json.dumps(case)


def test_provenance_names_the_engine_version_and_package_hashes(ci_suite):
    out, summary, _ = ci_suite
    case = next(c for c in summary["cases"] if c["backend"] == "rapier" and c["scene"] == "head_on_equal")
    text = (out / case["result_file"]).read_text()
    record = tomllib.loads(text.split("\n", 1)[1])
    provenance = json.dumps(record)
    assert "@dimforge/rapier2d-compat 0.21.0" in provenance
    assert "package-lock.json" in provenance and "rapier.cjs" in provenance


def test_each_node_engine_starts_once_per_worker_not_once_per_case(ci_suite):
    # long_lived = true in engines_ci.toml: each worker (--jobs 2) starts an engine's adapter once
    # for all its cases and presets (a preset is a request option, not another program).
    out, summary, _ = ci_suite
    for engine in ENGINES:
        starts = calls = 0
        for c in summary["cases"]:
            if c["backend"] in (engine, f"{engine}[shipped]") and c["status"] == "completed":
                counters = tomllib.loads((out / c["result_file"]).read_text().split("\n", 1)[1]).get("counters", {})
                starts += counters.get("server_starts", 0)
                calls += counters.get("program_calls", 0)
        assert calls >= 8 and 1 <= starts <= 2, (engine, starts, calls)


def test_cost_is_the_engines_own_stepping_time_not_the_call(ci_suite):
    out, summary, _ = ci_suite
    case = next(c for c in summary["cases"] if c["backend"] == "rapier" and c["scene"] == "head_on_equal")
    record = tomllib.loads((out / case["result_file"]).read_text().split("\n", 1)[1])
    text = json.dumps(record)
    assert "call_wall_seconds" in text and "solver_seconds" in text, text[:2000]


def test_report_page_engines_side_by_side_shows_the_table_and_the_figure(ci_suite, tmp_path):
    out, summary, _ = ci_suite
    r = subprocess.run([COLLIDE, "report", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-2000:]
    page = out / "report" / "engines.html"
    assert page.exists()
    from selenium import webdriver  # Debian's python3-selenium, chromium, chromium-driver (install-deps.sh)
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1400,1800"):
        options.add_argument(arg)
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"), options=options)
    try:
        driver.get(page.as_uri())
        screenshot = tmp_path / "engines.png"
        driver.save_screenshot(str(screenshot))
        table = driver.find_element(By.ID, "engines-table")
        assert table.is_displayed()
        shown = {row.find_elements(By.TAG_NAME, "td")[0].text.strip("■ ").strip()
                 for row in table.find_elements(By.TAG_NAME, "tr")[1:]}
        assert {"box2d", "chipmunk", "chipmunk[shipped]"} | {f"{e}{p}" for e in ENGINES for p in ("", "[shipped]")} <= shown
        image = driver.find_element(By.CSS_SELECTOR, "#engines-work-precision img")
        assert image.is_displayed() and driver.execute_script("return arguments[0].naturalWidth", image) > 100
        top = driver.execute_script("return arguments[0].getBoundingClientRect().top", image)
        assert top < 1800, "the figure is not on the screenshot"
        for link in table.find_elements(By.TAG_NAME, "a"):  # every number links to a case record that exists
            assert pathlib.Path(link.get_attribute("href").removeprefix("file://")).exists(), link.get_attribute("href")
    finally:
        driver.quit()
    from PIL import Image
    with Image.open(screenshot) as shot:
        assert shot.size[0] >= 1400 and len(shot.convert("L").getcolors(1 << 16) or []) > 10  # not a blank page


def test_every_backend_gets_a_distinct_colour_and_marker():
    import sys
    sys.path.insert(0, str(ROOT / "validation" / "report"))
    import figures
    names = ["event", "step", "cpu", "opencl", "box2d", "box2d[shipped]", "chipmunk", "chipmunk[shipped]",
             "mine", "yours"] + [f"{e}{p}" for e in ENGINES for p in ("", "[shipped]")]
    figures.assign_styles(names)
    assert len({figures.colour(n) for n in names}) == len(names)
    assert len({figures.marker(n) for n in names}) == len(names)


def test_a_solver_without_contacts_gets_collision_rate_left_out_with_the_reason(tmp_path):
    suite = tmp_path / "suite.toml"
    suite.write_text(f"""name = "no-contacts"
scene_dir = "{ROOT / 'data' / 'scenes'}"
backends = ["event"]
reference = "event"
seeds = [1, 2]
warmup_fraction = 0
time_limit = 300
[output]
hdf5 = false
[solver.straight]
command = "/usr/bin/python3 {ROOT / 'tests' / 'engines' / 'no_contacts_solver.py'}"
[[scene]]
name = "box_gas_1000"
compare = "statistics"
duration = 0.2
dt = [2e-3]
""")
    out = tmp_path / "out"
    subprocess.run([COLLIDE, "validate", str(suite), "--out", str(out), "--jobs", "2"], capture_output=True, text=True)
    summary = json.loads((out / "summary.json").read_text())
    rate = [c for c in summary["checks"] if c["backend"] == "straight" and c["check"] == "collision_rate"]
    assert rate and all(c["status"] == "left_out" for c in rate), rate
    assert "does not report its contacts" in rate[0]["detail"]
