#!/usr/bin/env python3
"""Keeps the course honest: its exercises, figures and links against today's programs.

    check_course.py exercises COLLIDE   run every exercise's commands; each answer's
                                        <!-- expect: TEXT --> line must appear in the output
    check_course.py links               every image and relative link of docs/ resolves, every
                                        quoted line range (<!-- quote PATH:A-B -->) matches its file,
                                        and every file that starts with #! is executable
    check_course.py figures COLLIDE     docs/figures/make_figures.py runs on the library scenes,
                                        every axis of every figure is labelled with a unit, >= 150 dpi
    check_course.py lab COLLIDE         every coding exercise's worked solution passes
                                        `lab.py check` (with COLLIDE on the PATH: exercise 2.7
                                        runs `collide validate`) and a typical wrong answer
                                        (tests/docs/wrong_answers/NAME[--WHAT].py) is rejected,
                                        naming its slip (its "# hint:" line); other right answers
                                        (tests/docs/right_answers/) are accepted
    check_course.py facts COLLIDE [NAME...]
                                        statements of the text measured against runs: the collision
                                        virial, Galperin's circle, the Newton's-cradle lag, what
                                        a slope in log-log gives, the pair's second meeting, the
                                        stable root's errors, step on a step boundary, multi-contact
                                        steps, paired differences, a correlated series, the
                                        Lyapunov exponent, the five seeds' spreads and
                                        drift, the walls' collision rate, the grid fitted to
                                        small disks, three routes to one
                                        equilibrium, an event loop's 1e-9 push (caught in every
                                        scene only when declared exact), g(d) by the collision
                                        virial and by lines over four windows, |psi6| and the
                                        pressure across the hexatic transition at N = 72 and 870,
                                        the square boxes' pressures at N = 72, 224 and 870,
                                        Engel et al.'s table against its data file,
                                        self-diffusion against Enskog's, the velocity
                                        autocorrelation function (Green-Kubo, the 1/t tail), the
                                        equilibration cut from the data, the Metropolis slips'
                                        wall pressures, chapter 2's fixed cuts against the cut
                                        from the data, and wording found false; with NAMEs,
                                        only those statements
    check_course.py fact-names          the statements' names (CTest reads them from the FACTS
                                        table itself and makes a test of each)

An exercise is a "### Exercise" section of a chapter (docs/course/[1-9]-*.md): its first ```sh
block is the command a student runs, with `collide` meaning the built program, in a scratch
folder that sees the repository's data/ and docs/. A coding exercise also holds its worked
solution as `<!-- solution: FILE -->` and a ```python block, written to FILE in the scratch folder
before the commands run (its commands call `python3 docs/course/lab.py check NAME FILE`).
"""
import functools
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

from worked_solution import SOLUTION  # <!-- solution: FILE --> and its ```python block

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "data" / "scenes"
COURSE = ROOT / "docs" / "course"
MIN_EXERCISES = 3
MIN_CODING_EXERCISES = 5
# The page every chapter assumes read: install, PATH, scratch folder, units, notation.
BEFORE_YOU_START = COURSE / "0-before-you-start.md"


def chapters():
    pages = sorted(COURSE.glob("[1-9]-*.md"))
    if len(pages) != 5:
        sys.exit(f"expected five chapter pages in {COURSE}, found {[p.name for p in pages]}")
    if not BEFORE_YOU_START.exists():
        sys.exit(f"{BEFORE_YOU_START} is missing (install, PATH, scratch folder, units, notation)")
    return pages


def exercises(page):
    """(title, commands, expected lines, solution files) of every exercise on a chapter page."""
    found = []
    for section in re.split(r"(?m)^### ", page.read_text())[1:]:
        if not section.startswith("Exercise"):
            continue
        title = section.splitlines()[0]
        block = re.search(r"```sh\n(.*?)```", section, re.S)
        expects = re.findall(r"<!-- expect: (.*?) -->", section)
        if not block or not expects:
            sys.exit(f"{page.name}: '{title}' needs a ```sh block and at least one <!-- expect: --> line")
        found.append((title, block.group(1), expects, dict(SOLUTION.findall(section))))
    return found


def coding_exercises():
    """{lab.py check NAME: (page, worked solution)} over the chapters."""
    found = {}
    for page in chapters():
        for title, commands, _, solutions in exercises(page):
            for name, file in re.findall(r"lab\.py check (\S+) (\S+)", commands):
                if file not in solutions:
                    sys.exit(f"{page.name}: '{title}' checks {file} but has no <!-- solution: {file} --> block")
                found[name] = (page, solutions[file])
    return found


def scratch_environment(collide, scratch):
    bin_dir = scratch / "bin"
    bin_dir.mkdir()
    (bin_dir / "collide").symlink_to(pathlib.Path(collide).resolve())
    (bin_dir / "python3").symlink_to("/usr/bin/python3")  # Debian's numpy/h5py live there
    for name in ("data", "docs"):
        (scratch / name).symlink_to(ROOT / name)
    env = dict(os.environ)
    env["PATH"] = f"{bin_dir}:{env['PATH']}"
    return env


def check_exercises(collide):
    failures, count = [], 0
    for page in chapters():
        items = exercises(page)
        if len(items) < MIN_EXERCISES:
            failures.append(f"{page.name}: {len(items)} exercises, at least {MIN_EXERCISES} wanted")
        for title, commands, expects, solutions in items:
            count += 1
            with tempfile.TemporaryDirectory(prefix="collide-exercise-") as scratch:
                scratch = pathlib.Path(scratch)
                env = scratch_environment(collide, scratch)
                for file, code in solutions.items():
                    (scratch / file).write_text(code)
                done = subprocess.run(["bash", "-euo", "pipefail", "-c", commands], cwd=scratch, env=env,
                                      capture_output=True, text=True, timeout=600)
            if done.returncode != 0:
                failures.append(f"{page.name}: '{title}' exited {done.returncode}:\n{done.stderr[-2000:]}")
                continue
            missing = [e for e in expects if e not in done.stdout]
            if missing:
                failures.append(f"{page.name}: '{title}': the docs' answer {missing} is not what the "
                                f"command prints today:\n{done.stdout[-3000:]}")
    print(f"{count} exercises checked")
    return failures


def check_links():
    failures, images = [], 0
    for page in sorted((ROOT / "docs").rglob("*.md")):
        text = page.read_text()
        for is_image, target in re.findall(r"(!?)\[[^\]]*\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+://|#|mailto:", target):
                continue
            path = (page.parent / target.split("#")[0]).resolve()
            images += bool(is_image)
            if not path.exists():
                failures.append(f"{page.relative_to(ROOT)}: link to {target} does not resolve")
    for page in chapters():
        if "![" not in page.read_text():
            failures.append(f"{page.name}: a chapter without a figure")
    print(f"{images} image links checked")
    return failures


def check_scripts_run():
    """A script the docs tell a reader to run as `path/to/script.py ...` needs its execute bit: every
    file of the repository that starts with #! has it (validation/report/reading_numbers.py, run so
    on two pages, had lost it: 'Permission denied')."""
    skip = {"build", ".git", "node_modules"}
    failures, scripts = [], 0
    for folder, subfolders, files in os.walk(ROOT):
        subfolders[:] = sorted(d for d in subfolders if d not in skip)  # not walked at all
        for name in sorted(files):
            path = pathlib.Path(folder) / name
            with open(path, "rb") as f:
                if f.read(2) != b"#!":
                    continue
            scripts += 1
            if not os.access(path, os.X_OK):
                failures.append(f"{path.relative_to(ROOT)} starts with #! but is not executable (chmod +x, "
                                f"git update-index --chmod=+x)")
    print(f"{scripts} scripts checked for their execute bit")
    return failures


def check_quotes():
    """Code quoted on a page as <!-- quote PATH:A-B --> followed by a fenced block must be lines
    A to B of PATH, exactly: a quote that drifts from the source fails here."""
    failures, quoted = [], 0
    pattern = re.compile(r"<!-- quote ([^ :]+):(\d+)-(\d+) -->\n```[a-z]*\n(.*?)\n```", re.S)
    for page in sorted((ROOT / "docs").rglob("*.md")):
        for path, first, last, body in pattern.findall(page.read_text()):
            quoted += 1
            source = ROOT / path
            if not source.exists():
                failures.append(f"{page.relative_to(ROOT)}: quotes {path}, which does not exist")
                continue
            lines = source.read_text().split("\n")[int(first) - 1:int(last)]
            if "\n".join(lines) != body:
                failures.append(f"{page.relative_to(ROOT)}: the quote of {path}:{first}-{last} differs from the file")
    print(f"{quoted} code quotes checked")
    return failures


def check_figures(collide):
    with tempfile.TemporaryDirectory(prefix="collide-figures-out-") as out:
        done = subprocess.run(["/usr/bin/python3", str(ROOT / "docs/figures/make_figures.py"),
                               "--collide", collide, "--out", out], capture_output=True, text=True)
        made = sorted(p.name for p in pathlib.Path(out).glob("*.png"))
        failures = [] if done.returncode == 0 else [f"make_figures.py exited {done.returncode}:\n{done.stderr[-3000:]}"]
        failures += [f"{name}: {problem}" for name in made for problem in figure_problems(pathlib.Path(out) / name)]
    linked = set()
    for page in chapters():
        linked |= set(re.findall(r"\(\.\./figures/([^)]+\.png)\)", page.read_text()))
    missing = sorted(linked - set(made))
    print(f"{len(made)} figures made")
    return failures + ([f"figures linked by the course but not made by make_figures.py: {missing}"] if missing else [])


def figure_problems(png):
    """An axis without a unit, a colour scale without a colour bar, or fewer than 150 dpi.
    make_figures.py records every axis's labels in the PNG's "axes" text (JSON)."""
    import json
    from PIL import Image
    with Image.open(png) as image:
        dpi, text = image.info.get("dpi", (0, 0)), image.text
    problems = [] if min(dpi) >= 149.5 else [f"{min(dpi):.0f} dpi, 150 wanted"]
    if "axes" not in text:
        return problems + ["no axis labels recorded (make_figures.finish writes them)"]
    axes = json.loads(text["axes"])
    for axis in axes:
        for which in ("xlabel", "ylabel"):
            label = axis[which]
            if axis.get(f"{which}_categorical"):
                continue  # categories (backends, seeds) carry no unit
            if not label and axis.get(f"{which}_shared") and any(a[which] for a in axes if a is not axis):
                continue  # a panel sharing a labelled panel's axis
            if not re.search(r"\([^()]*\)\s*$", label or ""):
                problems.append(f"{which} {label!r} gives no unit in brackets at its end")
        if axis.get("colour_encodes_value") and not axis.get("colorbar"):
            problems.append("colour encodes a value but there is no colour bar")
    return problems


# --- Statements of the text, measured ---------------------------------------------------------

def run(collide, scene_text, backend, scratch, name, frames=True):
    scene = scratch / f"{name}.toml"
    scene.write_text(scene_text)
    out = scratch / f"{name}.h5"
    command = [collide, "run", str(scene), "--backend", backend, "--out", str(out)] + (["--frames"] if frames else [])
    subprocess.run(command, check=True, capture_output=True)
    return h5py.File(out, "r")


def set_key(text, key, value):
    return re.sub(rf"(?m)^{key}\s*=.*$", f"{key} = {value}", text, count=1)


def close(stated, measured, relative):
    return abs(stated - measured) <= relative * abs(measured)


def fact_virial(collide, scratch):
    """Chapter 2's worked virial example (head_on_equal in a periodic box, one collision) against
    the run: the virial m_i dv_i . d of the collision from the frames, and the code's pressure."""
    page = (COURSE / "2-many-disks-exactly.md").read_text()
    w = re.search(r"collision virial W = m_i Δ\*\*v\*\*_i · \*\*d\*\* = ([\d.]+)", page)
    p = re.search(r"the run prints `pressure ([\d.]+)`", page)
    if not w or not p:
        return ["2-many-disks-exactly.md: no worked virial example (\"collision virial W = m_i Δ**v**_i · "
                "**d** = ...\" and \"the run prints `pressure ...`\")"]
    text = (ROOT / "data/scenes/head_on_equal.toml").read_text().replace('"reflect"', '"periodic"')
    f = run(collide, text, "event", scratch, "virial")
    t, x, v = f["frames/time"][:], f["frames/position"][:], f["frames/velocity"][:]
    m = f["particles/mass"][:]
    k = int(np.argmax(np.any(v[1:] != v[:-1], axis=(1, 2))))  # the frame interval with the collision
    dv = v[k + 1, 0] - v[k, 0]
    tc = 1.5  # the scene's collision time; positions at contact from the free flight before it
    d = (x[k, 0] + v[k, 0] * (tc - t[k])) - (x[k, 1] + v[k, 1] * (tc - t[k]))
    virial = m[0] * float(dv @ d)
    counters = f["stats/counters"].attrs
    failures = []
    if not close(float(w.group(1)), virial, 1e-6):
        failures.append(f"2-many-disks-exactly.md: the page's collision virial W = {w.group(1)}, the run's "
                        f"m_i Δv_i · d = {virial:.6g}")
    if not close(float(p.group(1)), float(counters["pressure"]), 1e-5):
        failures.append(f"2-many-disks-exactly.md: the page's pressure {p.group(1)}, the run's {float(counters['pressure']):.6g}")
    area, duration = 40.0, float(counters["simulated_time"])
    by_formula = (float(counters["kinetic_integral"]) / duration + virial / (2 * duration)) / area
    if not close(float(p.group(1)), by_formula, 1e-5):
        failures.append(f"2-many-disks-exactly.md: P A = <K> + W/(2t) with the run's W gives {by_formula:.6g}, "
                        f"not the page's {p.group(1)}")
    return failures


def fact_galperin(collide, scratch):
    """Chapter 1's circle: with a = sqrt(m1) v1 on the horizontal axis, a wall collision only
    flips a (a horizontal jump) and a pair collision moves along a line of slope -sqrt(m1/m2)."""
    # Mass ratio 100 (31 collisions) and frames every 0.002: one collision per frame interval.
    text = (SCENES / "stiff/pi_billiard_k2.toml").read_text().replace("mass = 10000.0", "mass = 100.0")
    f = run(collide, set_key(text, "output_interval", "0.002"), "event", scratch, "pi")
    v, m = f["frames/velocity"][:, :, 0], f["particles/mass"][:]
    a, b = np.sqrt(m[0]) * v[:, 0], np.sqrt(m[1]) * v[:, 1]
    da, db = np.diff(a), np.diff(b)
    jumps = np.abs(da) + np.abs(db) > 1e-12
    wall = jumps & (np.abs(db) < 1e-12)
    pair = jumps & ~wall
    if wall.sum() != 15 or pair.sum() != 16:
        return [f"pi billiard at mass ratio 100: {wall.sum()} wall and {pair.sum()} pair jumps seen, 15 and 16 "
                "expected (31 collisions)"]
    failures = []
    if not np.allclose(a[1:][wall], -a[:-1][wall]):
        failures.append("pi_billiard_k2: a wall collision does more than flip a")
    slopes = db[pair] / da[pair]
    if not np.allclose(slopes, -np.sqrt(m[0] / m[1]), rtol=1e-6):
        failures.append(f"pi_billiard_k2: pair chords have slopes {slopes[:3]}, not -sqrt(m1/m2)")
    page = (COURSE / "1-one-collision.md").read_text()
    said = re.findall(r"[Ww]all collision[^.]*?\b(horizontal|vertical)\b", page)
    said += re.findall(r"\b(horizontal|vertical)[^.]{0,30}\(wall", page)
    if not said or any(word != "horizontal" for word in said):
        failures.append(f"1-one-collision.md: the run's wall collisions are horizontal jumps (b = sqrt(m2) v2 "
                        f"unchanged, a on the horizontal axis); the page says {said or 'nothing'}")
    if "−√(m₁/m₂)" not in page:
        failures.append("1-one-collision.md: the slope of the pair chords, −√(m₁/m₂), is not stated")
    return failures


def fact_cradle(collide, scratch):
    """Chapter 3's caption: the lasting lag of the far disk of Newton's cradle behind `event` at
    the end of the run, at dt = 0.1 and 0.02, read from the run files."""
    page = (COURSE / "3-many-disks-stepped.md").read_text()
    said = re.search(r"lasting lag[^0-9]*([\d.]+) at dt = 0\.1[^0-9]*([\d.]+) at dt = 0\.02", page)
    if not said:
        return ["3-many-disks-stepped.md: the cradle caption states no lasting lag "
                "(\"lasting lag ... X at dt = 0.1 ... Y at dt = 0.02\")"]
    text = (SCENES / "stiff/newtons_cradle.toml").read_text()
    exact = run(collide, text, "event", scratch, "cradle_event")["frames/position"][-1, 5, 0]
    failures = []
    for stated, dt in zip(said.groups(), ("0.1", "0.02")):
        f = run(collide, set_key(text, "dt", dt), "step", scratch, f"cradle_{dt}")
        lag = (exact - f["frames/position"][-1, 5, 0]) / f["frames/velocity"][-1, 5, 0]
        if not close(float(stated), lag, 0.05):
            failures.append(f"3-many-disks-stepped.md: the caption's lag at dt = {dt} is {stated}, the run's "
                            f"{lag:.3g}")
    return failures


def fact_slope():
    """Chapter 4: a slope in log-log is the observed order only against dt (or the number of
    steps); against run time it is -p only if the time is proportional to 1/dt. Every sentence
    of the chapter that ties a slope to an order must say which axis it is on."""
    page = (COURSE / "4-validating-a-solver.md").read_text()
    sentences = re.split(r"(?<=[.:;])\s+", re.sub(r"\s+", " ", page))
    failures = []
    for sentence in sentences:
        if "slope" in sentence and "order" in sentence and "dt" not in sentence:
            failures.append(f"4-validating-a-solver.md: \"{sentence[:120]}\" ties a slope to the order "
                            "without saying it is the slope against dt")
        if re.search(r"slope", sentence) and re.search(r"run time|wall time", sentence) \
                and not re.search(r"only if|only when|not", sentence):
            failures.append(f"4-validating-a-solver.md: \"{sentence[:120]}\" reads an order off the "
                            "error-against-run-time plot")
    if not any("slope" in s and "dt" in s and "order" in s for s in sentences):
        failures.append("4-validating-a-solver.md: no sentence says that the slope against dt is the order")
    return failures


def fact_reunion(collide, scratch):
    """Chapter 2: when the periodic head_on_equal pair meets a second time, from a run to t = 6
    (frames every 0.05; each contact time from the centre distance before it, closing at speed 2)."""
    page = (COURSE / "2-many-disks-exactly.md").read_text()
    said = re.search(r"meet again\s+only at t = ([\d.]+)", page)
    if not said:
        return ["2-many-disks-exactly.md: the worked virial example says not when the pair meets again"]
    text = (ROOT / "data/scenes/head_on_equal.toml").read_text().replace('"reflect"', '"periodic"')
    text = set_key(set_key(text, "duration", "6.0"), "output_interval", "0.05")
    f = run(collide, text, "event", scratch, "reunion")
    t, x, v = f["frames/time"][:], f["frames/position"][:, :, 0], f["frames/velocity"][:, :, 0]
    changed = np.flatnonzero(v[1:, 0] != v[:-1, 0])
    gap = np.abs(x[:, 0] - x[:, 1])
    gap = np.minimum(gap, 10.0 - gap)  # the nearer image across the periodic box of width 10
    meetings = [t[k] + (gap[k] - 1.0) / 2.0 for k in changed]
    if len(meetings) < 2:
        return [f"periodic head_on_equal: {len(meetings)} collision(s) up to t = 6, two expected"]
    if not close(float(said.group(1)), meetings[1], 1e-6):
        return [f"2-many-disks-exactly.md: the pair meets again at t = {said.group(1)} says the page, "
                f"at t = {meetings[1]:.6g} says the run"]
    return []


def enskog_excess(collide, scratch, boundary, cut, end, seeds=8):
    """box_gas_1000 on event from seeds 1-8: the collision rate over [0, cut] and over [cut, end]
    relative to Enskog's, 2 rho sigma g(sigma) sqrt(pi kT/m) with g(sigma) from Kolafa-Rottner's
    Z = 2.1517 (chapter 2.4), minus 1, in %: mean and standard error over the seeds of each."""
    text = set_key((SCENES / "box_gas_1000.toml").read_text(), "boundary", f'"{boundary}"')
    eta, free = 1000 * np.pi * 0.25 / 2500, 999 if boundary == "periodic" else 1000
    rate = lambda kt: 2 * 0.4 * (2.1517 - 1) / (2 * eta) * np.sqrt(np.pi * kt)
    rows = []
    for seed in range(1, seeds + 1):
        counts = []
        for duration in (cut, end):
            f = run(collide, set_key(set_key(text, "seed", str(seed)), "duration", repr(duration)), "event", scratch,
                    f"enskog_{boundary}{seed}_{duration}", frames=False)
            kt = float(f["metrics/kinetic_energy"][0]) / free  # (e = 1: K is conserved)
            counts.append(float(f["stats/counters"].attrs["events_pair"]))
        early, late = counts[0], counts[1] - counts[0]
        rows.append((2 * early / (1000 * cut) / rate(kt) - 1, 2 * late / (1000 * (end - cut)) / rate(kt) - 1))
    r = 100 * np.array(rows)
    return r.mean(axis=0), r.std(axis=0, ddof=1) / np.sqrt(seeds)


def fact_enskog_walls(collide, scratch):
    """Chapter 2.4: box_gas_1000's collision rate against Enskog's, with its walls and in a
    periodic box, over the first 10 time units and over 10-60, eight seeds (mean +- SE)."""
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    walls = re.search(r"the first 10 left out, give a rate \+([\d.]+) ± ([\d.]+) % above Enskog", page)
    periodic = re.search(r"give \+([\d.]+) ± ([\d.]+) % over the same window, Enskog's rate within its error, "
                         r"and −([\d.]+) ± ([\d.]+) % over the first 10 time units", page)
    if not walls or not periodic:
        return ["2-many-disks-exactly.md: section 2.4 does not state the measured excess of box_gas_1000's "
                "collision rate over Enskog's, with walls and in a periodic box"]
    failures = []
    (_, wall_late), (_, wall_se) = enskog_excess(collide, scratch, "reflect", 10.0, 60.0)
    (per_early, per_late), (per_early_se, per_late_se) = enskog_excess(collide, scratch, "periodic", 10.0, 60.0)
    for what, said, measured in (("walls, 10-60", walls.groups(), (wall_late, wall_se)),
                                 ("periodic, 10-60", periodic.groups()[:2], (per_late, per_late_se)),
                                 ("periodic, 0-10", periodic.groups()[2:], (-per_early, per_early_se))):
        if any(abs(float(s) - m) > 0.006 for s, m in zip(said, measured)):
            failures.append(f"2-many-disks-exactly.md: {what}: the page says {said[0]} ± {said[1]} %, the runs "
                            f"{measured[0]:.2f} ± {measured[1]:.2f} %")
    return failures


def fact_root_rounding():
    """Chapter 2, the stable root: its numbers on the checker's second pair (a gap of 1e-10), for the
    stable and the textbook forms, against the exact root and the root of the rounded coefficients."""
    sys.path.insert(0, str(COURSE))
    import lab_check
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    case = lab_check.root_cases()[1]
    exact, rounded = lab_check.exact_contact_time(*case), lab_check.rounded_coefficient_root(*case)
    dx, dy, ux, uy, sigma = case
    b, c, uu = dx * ux + dy * uy, dx * dx + dy * dy - sigma * sigma, ux * ux + uy * uy
    textbook = (-b - np.sqrt(b * b - uu * c)) / uu
    stable = 0.0
    for q in lab_check.root_cases():
        root = lab_check.rounded_coefficient_root(*q)
        if root is not None:
            qb, qc, qu = q[0] * q[2] + q[1] * q[3], q[0] ** 2 + q[1] ** 2 - q[4] ** 2, q[2] ** 2 + q[3] ** 2
            stable = max(stable, abs(qc / (-qb + np.sqrt(qb * qb - qu * qc)) - root) / root)
    wanted = {"stable form's largest error": (r"within ([\d.]+e−\d+) of the root of the rounded coefficients",
                                              max(stable, 1.1e-16)),
              "c's rounding": (r"\(([\d.]+e−\d+) on the second pair", abs(rounded - exact) / exact),
              "textbook from the rounded-coefficient root": (r"textbook form is off by ([\d.]+e−\d+) from that root",
                                                             abs(textbook - rounded) / rounded),
              "textbook from the exact root": (r"and ([\d.]+e−\d+) from the exact one", abs(textbook - exact) / exact)}
    failures = []
    for what, (pattern, measured) in wanted.items():
        said = re.search(pattern, page)
        if not said:
            failures.append(f"2-many-disks-exactly.md: the stable root's section states no {what}")
        elif not 0.5 <= float(said.group(1).replace("−", "-")) / measured <= 1.5:
            failures.append(f"2-many-disks-exactly.md: {what} is {said.group(1)} on the page, {measured:.1e} computed")
    return failures


def fact_step_boundary(collide, scratch):
    """Chapter 3, exercise 3.3: at which dt `step` finds head_on_equal's collision (t = 1.5, on a
    step boundary) on time and at which a full step late, read from runs against `event`."""
    page = re.sub(r"\s+", " ", (COURSE / "3-many-disks-stepped.md").read_text())
    said = re.search(r"`step` is a full step late at dt = (.*?) and on time at dt = (.*?)\. [A-Z]", page)
    if not said:
        return ["3-many-disks-stepped.md: exercise 3.3 does not say at which dt `step` is a full step late "
                "and at which on time"]
    text = (SCENES / "head_on_equal.toml").read_text()
    exact = run(collide, text, "event", scratch, "boundary_event")["frames/position"][-1]
    failures = []
    for verdict, listed in zip(("late", "on time"), said.groups()):
        for dt in re.findall(r"[\d.]+e-\d+", listed):
            error = np.max(np.linalg.norm(run(collide, set_key(text, "dt", dt), "step", scratch, f"b{dt}")
                                          ["frames/position"][-1] - exact, axis=1))
            measured = "late" if abs(error - float(dt)) < 1e-3 * float(dt) else "on time" if error < 1e-9 else "?"
            if measured != verdict:
                failures.append(f"3-many-disks-stepped.md: at dt = {dt} the page says `step` is {verdict}, the run's "
                                f"error is {error:.3e} ({measured})")
    return failures


def fact_multi_contact(collide, scratch):
    """Chapter 3, exercise 3.5: how far the counted multi-contact disk-steps lie from the
    independent-collision guess, in Poisson standard deviations, from a run."""
    page = re.sub(r"\s+", " ", (COURSE / "3-many-disks-stepped.md").read_text())
    said = re.search(r"([\d.]+) Poisson standard deviations \(√([\d.]+)", page)
    if not said:
        return ["3-many-disks-stepped.md: exercise 3.5 does not say how many standard deviations the count "
                "lies from the independent guess"]
    f = run(collide, (SCENES / "box_gas_1000.toml").read_text(), "step", scratch, "multi", frames=False)
    counted = float(f["stats/counters"].attrs["multi_contact_disks"])
    nu = 2.6002  # exercise 2.2's measured collision rate, checked there
    guess = nu ** 2 * 1e-3 * 10 * 1000 / 2
    z = (guess - counted) / np.sqrt(guess)
    failures = []
    if abs(float(said.group(1)) - z) > 0.05 or not close(float(said.group(2)), guess, 0.01):
        failures.append(f"3-many-disks-stepped.md: the page puts the count {said.group(1)} standard deviations "
                        f"(sqrt {said.group(2)}) below the guess; the run's {counted:g} is {z:.2f} below {guess:.1f}")
    if "include this very scene" not in page:
        failures.append("3-many-disks-stepped.md: exercise 3.5 compares with a fit without saying the fit "
                        "includes this scene")
    return failures


GOLDEN = (np.sqrt(5) - 1) / 2


def phase_errors(collide, scratch, backend, dt):
    """The suite's trajectory error of `backend` on head_on_equal at each of six replicate phases:
    replicate k starts frac(k phi) dt along the free flight (validation/compare/phase_shift.h);
    the largest position error over the output times, relative to r_min = 0.5."""
    errors = []
    for k in range(1, 7):
        shift = (k * GOLDEN) % 1.0 * dt
        text = set_key((SCENES / "head_on_equal.toml").read_text(), "dt", repr(dt))
        text = text.replace("x = 3.0,", f"x = {3.0 + shift!r},").replace("x = 7.0,", f"x = {7.0 - shift!r},")
        exact = run(collide, text, "event", scratch, f"phase{k}_event")["frames/position"][:]
        stepped = run(collide, text, backend, scratch, f"phase{k}_{backend}")["frames/position"][:]
        errors.append(np.max(np.linalg.norm(stepped - exact, axis=2)) / 0.5)
    return np.array(errors)


def fact_pairing(collide, scratch):
    """Chapter 4: the correlation r of `step`'s and `cpu`'s per-phase errors that the page states
    (it decides whether pairing narrows or widens the error of their difference), from runs."""
    page = re.sub(r"\s+", " ", (COURSE / "4-validating-a-solver.md").read_text())
    said = set(re.findall(r"r = (−?[\d.]+) at dt = ([\d.]+e-\d+)", page))
    if not said:
        return ["4-validating-a-solver.md: no measured correlation (\"r = ... at dt = ...\") behind the "
                "advice on paired differences"]
    failures = []
    for r, dt in sorted(said):
        measured = np.corrcoef(phase_errors(collide, scratch, "step", float(dt)),
                               phase_errors(collide, scratch, "cpu", float(dt)))[0, 1]
        if abs(float(r.replace("−", "-")) - measured) > 0.02:
            failures.append(f"4-validating-a-solver.md: r = {r} at dt = {dt} on the page, {measured:.3f} in the runs")
    return failures


def fact_correlated_series(collide, scratch):
    """Chapter 4: the lag-1 correlation of the stationary series the block-averaging rule cites
    (exercise 4.4's kinetic energy of ten disks), and that the series levels off (block 50 within
    10 % of block 100 and above twice block 1) where the stepped gas's random walk did not."""
    page = re.sub(r"\s+", " ", (COURSE / "4-validating-a-solver.md").read_text())
    said = re.search(r"lag-1 correlation ([\d.]+) in exercise 4\.4", page)
    if not said:
        return ["4-validating-a-solver.md: the block-averaging rule cites no measured correlated series"]
    text = (SCENES / "periodic_gas.toml").read_text().replace("count = 1000", "count = 200")
    text = set_key(text.replace("box = [0.0, 0.0, 60.0, 60.0]", "box = [0.0, 0.0, 26.8, 26.8]"), "duration", "200.0")
    v = run(collide, text, "event", scratch, "ten")["frames/velocity"][:]
    k = (v[:, :10] ** 2).sum(axis=(1, 2)) / 2
    sys.path.insert(0, str(COURSE))
    import lab_check
    se = {b: lab_check.reference_block_error(k, b) for b in (1, 50, 100)}
    failures = []
    if abs(float(said.group(1)) - np.corrcoef(k[:-1], k[1:])[0, 1]) > 0.01:
        failures.append(f"4-validating-a-solver.md: lag-1 correlation {said.group(1)} on the page, "
                        f"{np.corrcoef(k[:-1], k[1:])[0, 1]:.2f} in the run")
    if not (abs(se[50] / se[100] - 1) < 0.1 and se[100] > 2 * se[1]):
        failures.append(f"exercise 4.4's series has no plateau: block standard errors {se}")
    return failures


def periodic_gas_seeds(collide, scratch, drift):
    """periodic_gas on event from seeds 1-5, 2 time units, its Maxwell draw's drift `drift`:
    per seed the pressure counter P, Z with kT = K_int/(N - 1) (the centre-of-mass frame's
    kinetic energy over the degrees of freedom), Z with kT = K/N, K_cm in units of kT, and kT."""
    text = set_key((SCENES / "periodic_gas.toml").read_text(), "duration", "2.0")
    text = text.replace("velocity = { maxwell = 1.0 }", f'velocity = {{ maxwell = 1.0, drift = "{drift}" }}')
    rows = []
    for seed in range(1, 6):
        f = run(collide, set_key(text, "seed", str(seed)), "event", scratch, f"gas{seed}{drift}", frames=False)
        c, m = f["stats/counters"].attrs, f["particles/mass"][:]
        n, t = len(m), float(c["simulated_time"])
        k_cm = (f["metrics/momentum_x"][0] ** 2 + f["metrics/momentum_y"][0] ** 2) / (2 * m.sum())
        k, w = float(c["kinetic_integral"]) / t, float(c["virial_sum"]) / (2 * t)
        kt = (k - k_cm) / (n - 1)
        rows.append((float(c["pressure"]), 1 + w / (n * kt), 1 + w / k, k_cm / kt, kt))
    return np.array(rows)


def fact_replicates(collide, scratch):
    """Chapter 4's five seeds: the spread of the pressure and of Z with each seed's own kT, the
    centre of mass a raw draw leaves, and how far reading kT as K/N moves Z."""
    page = re.sub(r"\s+", " ", (COURSE / "4-validating-a-solver.md").read_text())
    spreads = re.search(r"P spreads by ([\d.]+) % \(standard deviation over the mean\) and Z by ([\d.]+) %", page)
    drift = re.search(r"K_cm = ([\d.]+) to ([\d.]+) kT.*?moves Z by at most ([\d.]+) %", page)
    temperatures = re.search(r"the seeds' temperatures, kT = ([\d.]+) to ([\d.]+),", page)
    if not spreads or not drift or not temperatures:
        return ["4-validating-a-solver.md: the five seeds' figure states no spread of P and of Z with each "
                "seed's own kT, or no centre-of-mass drift of a raw draw"]
    removed, raw = periodic_gas_seeds(collide, scratch, "removed"), periodic_gas_seeds(collide, scratch, "raw")
    spread = lambda x: 100 * x.std(ddof=1) / x.mean()
    measured = {"P's spread": (spreads.group(1), spread(removed[:, 0]), 0.05),
                "Z's spread": (spreads.group(2), spread(removed[:, 1]), 0.05),
                "the smallest K_cm": (drift.group(1), raw[:, 3].min(), 0.005),
                "the largest K_cm": (drift.group(2), raw[:, 3].max(), 0.005),
                "Z's shift with K/N": (drift.group(3), 100 * np.max(np.abs(raw[:, 2] / raw[:, 1] - 1)), 0.005),
                "the lowest kT": (temperatures.group(1), removed[:, 4].min(), 0.0005),
                "the highest kT": (temperatures.group(2), removed[:, 4].max(), 0.0005)}
    failures = [f"4-validating-a-solver.md: {what} is {said} on the page, {value:.3f} in the runs"
                for what, (said, value, slack) in measured.items() if abs(float(said) - value) > slack + 1e-9]
    if not np.allclose(raw[:, 1], removed[:, 1], rtol=1e-4):
        failures.append(f"periodic_gas: Z with a raw drift {raw[:, 1]} differs from Z without {removed[:, 1]}")
    return failures


def small_disks_in_cells(collide, scratch, cell):
    """Exercise 5.3's run: polydisperse_1_100 with its ten large disks made small (2010 disks of
    radius 0.01), 10 time units on event in cells of edge `cell`: the cell crossings per
    collision and the processor time per collision (the least of two runs, the process's)."""
    import resource
    text = (SCENES / "stiff/polydisperse_1_100.toml").read_text()
    text = text.replace("radius = 1.0\nmass = 100.0", "radius = 0.01\nmass = 0.01")
    text = set_key(set_key(text, "duration", "10.0"), "output_interval", "10.0") + f"\n[backend.event]\ncell_size = {cell}\n"
    seconds = []
    for attempt in range(2):
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
        f = run(collide, text, "event", scratch, f"cells{cell}_{attempt}", frames=False)
        seconds.append(resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before)
    c = f["stats/counters"].attrs
    return float(c["events_cell"]) / float(c["events_pair"]), min(seconds) / float(c["events_pair"])


def fact_fitted_grid(collide, scratch):
    """Chapter 5, exercise 5.3: cells fitted to the small disks (0.02) against the large disks'
    (2): the crossings per collision the page states, and that the fine grid costs more per
    collision by the page's factor (within 2x: the time of a shared machine)."""
    page = re.sub(r"\s+", " ", (COURSE / "5-making-it-fast.md").read_text())
    crossings = re.search(r"([\d.]+) crossings per collision with cells of 2, ([\d.]+) with 0\.45, ([\d.]+) with 0\.02", page)
    dearer = re.search(r"the grid fitted to the small disks is ([\d.]+) times \*dearer\*", page)
    if not crossings or not dearer:
        return ["5-making-it-fast.md: exercise 5.3 states no measured crossings per collision or cost of the grid "
                "fitted to the small disks"]
    measured = {cell: small_disks_in_cells(collide, scratch, cell) for cell in ("2", "0.45", "0.02")}
    failures = [f"5-making-it-fast.md: {said} crossings per collision with cells of {cell} on the page, "
                f"{measured[cell][0]:.3g} in the run"
                for cell, said in zip(("2", "0.45", "0.02"), crossings.groups())
                if not close(float(said), measured[cell][0], 0.01)]
    ratio = measured["0.02"][1] / measured["2"][1]
    if os.environ.get("COLLIDE_SANITIZED"):
        # AddressSanitizer's checks cost more per memory access than per arithmetic operation,
        # and the fine grid is all memory: 24.8 times under the dev preset, 8.5 in release.
        print(f"fitted_grid: cost ratio {ratio:.1f} not judged: a sanitized build (COLLIDE_SANITIZED) times its "
              f"checks, not the grid")
    elif not 0.5 <= float(dearer.group(1)) / ratio <= 2:
        failures.append(f"5-making-it-fast.md: cells of 0.02 cost {dearer.group(1)} times cells of 2 per collision "
                        f"on the page, {ratio:.1f} times in the runs")
    return failures


SAMPLING_BOX = ["--set", "particles.0.count=72", "--set", "particles.0.columns=9", "--set", "particles.0.spacing=0.955",
                "--set", "particles.0.radius=0.37125762464284556", "--set", "world.box=[0.0, 0.0, 9.0, 6.928203230275509]",
                "--set", "run.duration=2000", "--set", "run.output_interval=10"]


def route_pressure(collide, scratch, backend, name, extra=()):
    """beta P d^2 and its batch-means error of the 72-disk box of chapter 4.6 on `backend`, with
    the further `--set` options `extra`; the run file is scratch/NAME.h5."""
    out = scratch / f"{name}.h5"
    subprocess.run([collide, "run", str(SCENES / "physics/hard_disk_fluid.toml"), "--backend", backend,
                    "--out", str(out), *SAMPLING_BOX, *extra], check=True, capture_output=True)
    c = h5py.File(out, "r")["stats/counters"].attrs
    return float(c["beta_pressure"]), float(c["beta_pressure_error"])


def fact_sampling(collide, scratch):
    """Chapter 4.6: the three routes' pressures and errors in its table, the z of each pair, and
    ecmc's finite-size points at N = 72 (the 1152-disk ones are left to the page's command)."""
    page = re.sub(r"\s+", " ", (COURSE / "4-validating-a-solver.md").read_text())
    rows = {b: re.search(rf"\| `{b}`, [^|]*\| ([\d.]+) \| ([\d.]+) \|", page) for b in ("event", "ecmc", "metropolis")}
    z = re.search(r"z = ([\d.]+) for `event` against `ecmc`, ([\d.]+) against `metropolis`, ([\d.]+) between", page)
    small = re.search(r"2\.(\d+) and 2\.(\d+) \(± [\d.]+\) at N = 72", page)
    if not all(rows.values()) or not z or not small:
        return ["4-validating-a-solver.md: section 4.6 states no table of the three routes' pressures, their "
                "z, or ecmc's pressure at N = 72"]
    measured = {b: route_pressure(collide, scratch, b, f"route_{b}") for b in rows}
    failures = [f"4-validating-a-solver.md: {b}: {rows[b].group(1)} ± {rows[b].group(2)} on the page, "
                f"{p:.6g} ± {e:.3g} in the run" for b, (p, e) in measured.items()
                if abs(float(rows[b].group(1)) - p) > 1e-5 or not close(float(rows[b].group(2)), e, 0.01)]
    pairs = (("event", "ecmc"), ("event", "metropolis"), ("ecmc", "metropolis"))
    for said, (a, b) in zip(z.groups(), pairs):
        value = abs(measured[a][0] - measured[b][0]) / np.hypot(measured[a][1], measured[b][1])
        if abs(float(said) - value) > 0.01:
            failures.append(f"4-validating-a-solver.md: z = {said} for {a} against {b} on the page, {value:.2f} computed")
    longer = ["--set", "run.duration=4000"]
    for seed, digits in zip((1, 2), small.groups()):
        p, _ = route_pressure(collide, scratch, "ecmc", f"ecmc_seed{seed}", longer + ["--set", f"seed={seed}"])
        if abs(float(f"2.{digits}") - p) > 1e-4:
            failures.append(f"4-validating-a-solver.md: ecmc at N = 72, seed {seed}: 2.{digits} on the page, {p:.5f} run")
    return failures


def fact_lyapunov():
    """Chapter 2.5: the Lyapunov exponent the page states, against one seed of the same
    tangent-dynamics measurement (docs/tools/lyapunov.py): within three of its per-seed spreads."""
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    said = re.search(r"--disks (\d+) --seeds (\d+) --time ([\d.]+) --transient ([\d.]+) N = \d+, rho = ([\d.]+), "
                     r"kT = 1: lambda = ([\d.]+) \+- ([\d.]+) per time unit", page)
    if not said:
        return ["2-many-disks-exactly.md: section 2.5 states no Lyapunov exponent measured by tangent dynamics "
                "with its error (docs/tools/lyapunov.py)"]
    sys.path.insert(0, str(ROOT / "docs" / "tools"))
    import lyapunov
    disks, seeds, duration, transient, rho, lam, se = (float(g) for g in said.groups())
    one, _ = lyapunov.exponent(int(disks), rho, duration, transient, seed=1)
    spread = se * np.sqrt(seeds)
    if abs(one - lam) > 3 * spread:
        return [f"2-many-disks-exactly.md: lambda = {lam} +- {se} on the page; seed 1 of the same measurement "
                f"gives {one:.3f}, more than three per-seed spreads ({spread:.3f}) away"]
    return []


def fact_wording():
    """Statements that are false as worded, found by earlier reviews."""
    wrong = {"1-one-collision.md": ["The second law fixes J"],  # the contact law (restitution) fixes J
             # shadowing is proved for uniformly hyperbolic systems, not for hard disks; the hexatic
             # has short-range positional order, not none
             "2-many-disks-exactly.md": ["the computed trajectory is an exact trajectory", "no positional order",
                                         "within the 0.9 % statistical error"],
             # the golden-ratio phases are fixed, not a random sample: their spread does not shrink
             "4-validating-a-solver.md": ["shrink the standard errors as 1/√n"]}
    return [f"{name}: \"{phrase}\" is false as worded"
            for name, phrases in wrong.items() for phrase in phrases
            if phrase in re.sub(r"\s+", " ", (COURSE / name).read_text())]


def fact_declared_exact(collide, scratch):
    """Exercise 2.7: the event loop that pushes each pair 1e-9 apart after its collision fails only
    the periodic scene held to a stepped solver's limits, and every scene as lab.py check runs it,
    declared exact."""
    sys.path.insert(0, str(COURSE))
    import lab_event_loop  # the checker's own validate(), so a checker that stops declaring exact fails here
    failures = []
    nudge = ROOT / "tests/docs/wrong_answers/event_loop--nudge.py"
    undeclared = scratch / "nudge-undeclared"
    subprocess.run([collide, "validate", str(lab_event_loop.SUITE), "--out", str(undeclared), "--jobs", "2",
                    "--python-solver", f"you={nudge}:EventLoop"], capture_output=True, text=True)
    for declared, want, summary in (
            (False, {"chaotic_periodic"}, json.loads((undeclared / "summary.json").read_text())),
            (True, {"head_on_equal", "glancing", "head_on_mass_ratio_10", "newtons_cradle", "chaotic_walled",
                    "chaotic_periodic"}, lab_event_loop.validate(nudge, scratch / "nudge-declared", collide))):
        failed = {c["scene"] for c in summary["checks"] if c["backend"] == "you" and c["status"] == "fail"}
        if failed != want:
            claim = "declared exact" if declared else "declared as nothing"
            failures.append(f"2-many-disks-exactly.md: the pushed-apart event loop {claim} fails in "
                            f"{sorted(failed)}, the text says in {sorted(want)}")
    return failures


# The fluid of chapter 2.7 and exercise 2.8 (physics/hard_disk_fluid.toml at a chosen area
# fraction: 100 time units, a frame every 0.25, the structure from t = 20 on).
FLUID_RADIUS = {"0.3": "0.2944240825689061", "0.5": "0.3800998561705903", "0.65": "0.433380515089424"}
CONTACT_WINDOWS = ("0.2", "0.1", "0.05", "0.025")


def fluid_run(collide, out, eta, interval):
    """The fluid of 2.7 at `eta`, 100 time units with a frame every `interval`, written to out."""
    subprocess.run([collide, "run", str(SCENES / "physics/hard_disk_fluid.toml"), "--backend", "event", "--frames",
                    "--out", str(out), "--set", f"particles.0.radius={FLUID_RADIUS[eta]}", "--set", "run.duration=100",
                    "--set", f"run.output_interval={interval}"], check=True, capture_output=True)
    return out


def fluid_structure(collide, scratch, eta):
    """The exercise-2.8 run of the fluid at `eta`: its scene, frames from t = 20, diameter and
    lab_structure.routes (Z by the virial and the contact route)."""
    sys.path.insert(0, str(ROOT / "docs" / "course"))
    import lab_structure
    out = fluid_run(collide, scratch / f"fluid{eta}.h5", eta, "0.25")
    c = lab_structure.collide_module(collide)
    with h5py.File(out, "r") as f:
        frames = f["frames/position"][:][f["frames/time"][:] >= 20]
        scene = c.Scene.from_toml(f.attrs["scene_text"])
    return c, scene, frames, 2 * float(FLUID_RADIUS[eta]), lab_structure.routes(out, 20.0)


def contact_by_window(c, scene, frames, d, window):
    """g(d) by the line through 10 bins over [d, (1 + window) d], and its error over 10 blocks."""
    k = len(frames) // 10
    values = [c.pair_correlation(scene, frames[b * k:(b + 1) * k], d, window * d, 10)["contact"] for b in range(10)]
    return float(np.mean(values)), float(np.std(values, ddof=1) / np.sqrt(10))


def fact_pair_correlation(collide, scratch):
    """Chapter 2.7: the table of g(d) by the collision virial and by the line through [d, (1 + w) d]
    for four windows w, at eta = 0.5 and 0.65, each value and error as the runs give them."""
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    failures = []
    for eta in ("0.5", "0.65"):
        row = re.search(rf"\| {eta} \| ([\d.]+) ± ([\d.]+) \|" + r" ([\d.]+) ± ([\d.]+) \|" * 4, page)
        if not row:
            failures.append(f"2-many-disks-exactly.md: section 2.7 has no row of g(d) by window at eta = {eta}")
            continue
        c, scene, frames, d, routes = fluid_structure(collide, scratch, eta)
        measured = [((routes["z_virial"] - 1) / (2 * float(eta)), routes["z_virial_error"] / (2 * float(eta)))]
        measured += [contact_by_window(c, scene, frames, d, float(w)) for w in CONTACT_WINDOWS]
        said = [float(v) for v in row.groups()]
        for k, (what, (value, error)) in enumerate(zip(("virial",) + CONTACT_WINDOWS, measured)):
            if abs(said[2 * k] - value) > 0.0015 or abs(said[2 * k + 1] - error) > 0.0015:
                failures.append(f"2-many-disks-exactly.md: g(d) at eta = {eta}, {what}: {said[2 * k]} ± "
                                f"{said[2 * k + 1]} on the page, {value:.3f} ± {error:.3f} in the run")
    return failures


def fact_hexatic(collide, scratch):
    """Chapter 2.8: each row of the table of |psi6| and beta P d^2 (N, eta), rerun through the
    figure script's own hexatic_point (the same scene text, radius and run length), and the
    0.708 point with the radius one ulp larger, which the text says lands elsewhere."""
    sys.path.insert(0, str(ROOT / "docs" / "figures"))
    import make_figures
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    rows = re.findall(r"\| (72|870) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) ± ([\d.]+) \| (yes|no) \|", page)
    nudged = re.search(r"one ulp larger \(([\d.]+) instead of ([\d.]+)\) gives βPd² = ([\d.]+)", page)
    if len(rows) < 4 or not nudged:
        return ["2-many-disks-exactly.md: section 2.8 has no table of |Ψ₆| and βPd² by N and η, or no one-ulp rerun"]
    lab = make_figures.Lab(collide, scratch)
    boxes = {str(disks): box for disks, *box in make_figures.HEXATIC_BOXES}
    failures = []
    for disks, eta, psi, pressure, error, mixed in rows:
        name, area, duration = boxes[disks]
        p = make_figures.hexatic_point(lab, int(disks), name, area, duration, float(eta))
        measured = (p["psi6"], p["beta_pressure"], p["beta_pressure_error"], "yes" if p["mixed"] else "no")
        if (abs(float(psi) - measured[0]) > 0.0015 or abs(float(pressure) - measured[1]) > 0.0015
                or abs(float(error) - measured[2]) > 0.0015 or mixed != measured[3]):
            failures.append(f"2-many-disks-exactly.md: N = {disks}, eta = {eta}: |psi6| {psi}, beta P d^2 {pressure} ± "
                            f"{error}, mixed {mixed} on the page; the run: {measured[0]:.3f}, {measured[1]:.3f} ± "
                            f"{measured[2]:.3f}, {measured[3]}")
    name, area, duration = boxes["870"]
    radius = float(np.sqrt(0.708 * area / (870 * np.pi)))
    scene = lab.scene(name, radius=repr(np.nextafter(radius, 1.0)), duration=repr(duration), output_interval="1.0")
    other = float(lab.run(scene, "event")["stats"]["counters"]["beta_pressure"])
    if (nudged.group(1), nudged.group(2)) != (repr(np.nextafter(radius, 1.0)), repr(radius)) \
            or abs(float(nudged.group(3)) - other) > 0.0015:
        failures.append(f"2-many-disks-exactly.md: the radius one ulp larger ({nudged.group(1)} for {nudged.group(2)}) "
                        f"gives {nudged.group(3)} on the page; the run: radius {np.nextafter(radius, 1.0)!r} for "
                        f"{radius!r}, {other:.3f}")
    return failures


FINITE_SIZE_ROW = re.compile(r"\| (72|224|870) \| `(event|ecmc)`, (\d+) seeds × ([\d.]+) \| ([\d., ]+) \| ([\d.]+) ± "
                             r"([\d.]+) \| ([\d.]+)\((\d+)\) \| ([−-]?[\d.]+) \|")


def fact_finite_size(collide, scratch, disks_of_rows):
    """Chapter 2.8, finite size: Li et al.'s square boxes at eta = 0.670 (N = 72, 224, 870) on
    `event` and `ecmc`, the rows of N = disks_of_rows (one test per N: the N = 224 run of `event`
    alone takes over 10 minutes under the sanitizers). Seed 1 of each row is rerun with the
    row's run.duration; the mean, its standard error from the seeds' spread and z against the
    published value are recomputed from the seeds the page states."""
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    rows = FINITE_SIZE_ROW.findall(page)
    if {(n, b) for n, b, *_ in rows} != {(n, b) for n in ("72", "224", "870") for b in ("event", "ecmc")}:
        return ["2-many-disks-exactly.md: section 2.8 has no table of the square boxes' pressures at eta = 0.670 "
                "on event and ecmc for N = 72, 224 and 870"]
    failures = []
    for disks, backend, seeds, duration, values, mean, error, li, li_digits, z in rows:
        if disks != disks_of_rows:
            continue
        said = [float(v) for v in values.split(",")]
        where = f"2-many-disks-exactly.md: N = {disks} on {backend}"
        if len(said) != int(seeds):
            failures.append(f"{where}: {seeds} seeds named, {len(said)} values given")
            continue
        out = scratch / f"square{disks}_{backend}.h5"
        subprocess.run([collide, "run", str(SCENES / f"physics/li2022_n{disks}_square.toml"), "--backend", backend,
                        "--out", str(out), "--set", "seed=1", "--set", f"run.duration={duration}"],
                       check=True, capture_output=True)
        first = float(h5py.File(out, "r")["stats/counters"].attrs["beta_pressure"])
        if abs(first - said[0]) > 1e-4:
            failures.append(f"{where}: seed 1 gives {said[0]} on the page, {first:.5f} in the run")
        li_error = int(li_digits) * 10.0 ** -len(li.split(".")[1])
        spread = np.std(said, ddof=1) / np.sqrt(len(said))
        computed = (np.mean(said), spread, (np.mean(said) - float(li)) / np.hypot(spread, li_error))
        stated = (float(mean), float(error), float(z.replace("−", "-")))
        if any(abs(s - c) > tol for s, c, tol in zip(stated, computed, (1.5e-4, 1.5e-4, 0.06))):
            failures.append(f"{where}: mean, error and z {stated} on the page, {tuple(round(c, 5) for c in computed)} "
                            f"from its seeds")
    return failures


def fact_engel_table():
    """Chapter 2.8: every row of the table of Engel et al.'s (2013) pressures is a row of
    data/references/engel_2013.toml (eta, beta P d^2, N, method, standard error), the file the
    hexatic figure plots."""
    import tomllib
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    said = re.findall(r"\| (0\.\d+) \| ([\d.]+) \| (\d+)² \| (MPMC|EDMD) \| ([\d.]+) \|", page)
    if len(said) < 6:
        return ["2-many-disks-exactly.md: section 2.8 has no table of Engel et al.'s (2013) pressures"]
    rows = tomllib.loads((ROOT / "data/references/engel_2013.toml").read_text())["rows"]
    known = {(r["eta"], r["beta_pressure_d2"], r["disks"], r["method"], r["standard_error"]) for r in rows}
    return [f"2-many-disks-exactly.md: Engel et al.'s row eta {eta}, {p} at N = {side}², {method} ± {e} is no row of "
            f"engel_2013.toml" for eta, p, side, method, e in said
            if (float(eta), float(p), int(side) ** 2, method, float(e)) not in known]


def fact_diffusion(collide, scratch):
    """Chapter 2.9: the table of D(tau) / D_E at tau = 1, 2, 4 and 9 for eta = 0.3 and 0.5, and the
    collision rate of each run, recomputed by lab_structure.diffusion from the fluid runs of 2.7."""
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    sys.path.insert(0, str(ROOT / "docs" / "course"))
    import lab_structure
    failures = []
    for eta in ("0.3", "0.5"):
        row = re.search(rf"\| {eta} \| ([\d.]+) \|" + r" ([\d.]+) ± ([\d.]+) \|" * 4, page)
        if not row:
            failures.append(f"2-many-disks-exactly.md: section 2.9 has no row of D(tau) / D_E at eta = {eta}")
            continue
        fluid_structure(collide, scratch, eta)
        d = lab_structure.diffusion(scratch / f"fluid{eta}.h5", 20.0, (4, 8, 16, 36))
        said = [float(v) for v in row.groups()]
        measured = [d["nu"]] + [v for pair in zip(d["ratio"], d["error"]) for v in pair]
        if any(abs(s - m) > 0.0015 for s, m in zip(said, measured)):
            failures.append(f"2-many-disks-exactly.md: eta = {eta}: nu and D(tau) / D_E ± error {said} on the page, "
                            f"{[round(m, 3) for m in measured]} in the run")
    return failures


def fact_vacf(collide, scratch):
    """Chapter 2.9: the table of the velocity autocorrelation function (Green-Kubo's D(t) / D_E at
    t = 1, 4 and 10, its mean over [2, 4], the tail's slope and nu t C) at eta = 0.3 and 0.5, and
    the sentence that sets the mean beside the MSD slope, recomputed by lab_structure.vacf from
    the fluid runs of 2.7 with a frame every 0.025."""
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    sys.path.insert(0, str(ROOT / "docs" / "course"))
    import lab_structure
    lab_structure.collide_module(collide)   # the module beside this collide (the box of each run)
    pm, num = r" ([\d.]+) ± ([\d.]+) \|", r" ([\d.]+) \|"
    routes = re.search(r"over \[2, 4\] is the MSD table's τ = 2 cell, ([\d.]+) against ([\d.]+) ± ([\d.]+) at η = 0.3 "
                       r"and ([\d.]+) against ([\d.]+) ± ([\d.]+) at η = 0.5", page)
    if not routes:
        return ["2-many-disks-exactly.md: section 2.9 does not set Green-Kubo's mean over [2, 4] beside the MSD slope"]
    failures, beside = [], []
    for eta in ("0.3", "0.5"):
        row = re.search(rf"\| {eta} \|" + pm * 3 + num + r" [−-]([\d.]+) ± ([\d.]+) \|" + pm, page)
        if not row:
            failures.append(f"2-many-disks-exactly.md: section 2.9 has no row of the VACF's numbers at eta = {eta}")
            continue
        out = fluid_run(collide, scratch / f"vacf{eta}.h5", eta, "0.025")
        r = lab_structure.vacf(out, 20.0, 10.0)
        coarse = scratch / f"fluid{eta}.h5"   # the MSD table's run (fact_diffusion's), frames every 0.25
        msd = lab_structure.diffusion(coarse if coarse.exists() else fluid_run(collide, coarse, eta, "0.25"), 20.0, (8,))
        at = [int(round(t / 0.025)) for t in (1, 4, 10)]
        mean = lab_structure.green_kubo_mean(r, 2.0, 4.0)
        measured = [v for k in at for v in (r["d_gk"][k], r["d_gk_error"][k])] + [mean]
        measured += [-r["slope"], r["slope_error"], r["amplitude"], r["amplitude_error"]]
        said = [float(v) for v in row.groups()]
        places = [0.0015] * 7 + [0.015] * 2 + [0.0015] * 2   # the slope is stated to two places
        if any(abs(s_ - m) > p_ for s_, m, p_ in zip(said, measured, places)):
            failures.append(f"2-many-disks-exactly.md: eta = {eta}: the VACF's row {said} on the page, "
                            f"{[round(m, 3) for m in measured]} in the run")
        beside += [mean, msd["ratio"][0], msd["error"][0]]
    if beside and any(abs(float(s_) - m) > 0.0015 for s_, m in zip(routes.groups(), beside)):
        failures.append(f"2-many-disks-exactly.md: Green-Kubo's mean over [2, 4] against the MSD slope: "
                        f"{routes.groups()} on the page, {[round(m, 3) for m in beside]} in the runs")
    return failures


def fact_equilibration_cut(collide, scratch):
    """Chapter 4.4, the cut from the data: on hard_disk_fluid's pressure series (lab.py
    equilibration, 40 and 200 time units), the cut, tau_int and effective samples from t = 0 and
    from the cut, the means with the cut, whole and over the second half, the window from 2 to 4
    and the bias it leaves, and the long run's cut, mean and z against the short one."""
    page = re.sub(r"\s+", " ", (COURSE / "4-validating-a-solver.md").read_text())
    said = re.search(r"from t₀ = 0 the series has τ_int = ([\d.]+) windows and (\d+) effective samples, from t₀ = "
                     r"([\d.]+) it has τ_int = ([\d.]+) and (\d+), the most of any start: the cut is t = ([\d.]+), and "
                     r"βPd² = ([\d.]+) ± ([\d.]+) .*? the run reads ([\d.]+) ± ([\d.]+), .*? second half, ([\d.]+) ± "
                     r"([\d.]+), .*? from t = 2 to 4 still reads ([\d.]+), .*? by −([\d.]+) \(the mean from t = 2 less the "
                     r"mean from t = 4\).*? \(200 time units\) cuts at t = ([\d.]+) and gives ([\d.]+) ± ([\d.]+), ([\d.]+) "
                     r"combined errors", page)
    if not said:
        return ["4-validating-a-solver.md: section 4.4 states no equilibration cut from the data on hard_disk_fluid "
                "(the candidates' tau_int and effective samples, the means, the long run)"]
    sys.path.insert(0, str(COURSE))
    import lab_structure
    lab_structure.collide_module(collide)   # the module beside this collide, for lab_equilibration
    import lab_equilibration
    scene = SCENES / "physics/hard_disk_fluid.toml"
    short, long = lab_equilibration.cuts(scene), lab_equilibration.cuts(scene, 200)
    w, x, chosen = short["window"], short["series"], short["chosen"]
    cut = chosen["equilibration_cut"]
    effective = dict(chosen["candidates"])
    tau = lab_structure.collide().integrated_autocorrelation_time
    from_4 = int(round(4 / w))
    z = abs(long["chosen"]["mean"] - chosen["mean"]) / np.hypot(long["chosen"]["error"], chosen["error"])
    measured = [tau(x), effective[0], cut * w, tau(x[cut:]), effective[cut], cut * w, chosen["mean"], chosen["error"],
                short["whole"]["mean"], short["whole"]["error"], short["second_half"]["mean"],
                short["second_half"]["error"], x[int(round(2 / w)):from_4].mean(), x[from_4:].mean() - chosen["mean"],
                long["chosen"]["equilibration_cut"] * long["window"], long["chosen"]["mean"], long["chosen"]["error"], z]
    slack = [0.006, 0.6, 1e-9, 0.006, 0.6, 1e-9] + [6e-5] * 8 + [1e-9, 6e-5, 6e-5, 0.006]
    values = [float(v) for v in said.groups()]
    wrong = [k for k, (v, m, e) in enumerate(zip(values, measured, slack)) if abs(v - m) > e]
    failures = []
    if wrong:
        failures.append(f"4-validating-a-solver.md: the equilibration cut on hard_disk_fluid: the page says {values}, the "
                        f"runs {[round(float(m), 4) for m in measured]} (differing at positions {wrong})")
    return failures + stationary_series_cut(collide, scratch, page)


def stationary_series_cut(collide, scratch, page):
    """Chapter 4.4: the cut the rule takes on exercise 4.4's stationary series (the kinetic energy
    of ten disks of a gas in equilibrium), and the means without and with it."""
    said = re.search(r"on exercise 4\.4's ten disks it cuts (\d+) of (\d+) samples, and the mean moves from ([\d.]+) to "
                     r"([\d.]+) ± ([\d.]+)", page)
    if not said:
        return ["4-validating-a-solver.md: section 4.4 does not say what the cut does to exercise 4.4's stationary series"]
    text = (SCENES / "periodic_gas.toml").read_text().replace("count = 1000", "count = 200")
    text = set_key(text.replace("box = [0.0, 0.0, 60.0, 60.0]", "box = [0.0, 0.0, 26.8, 26.8]"), "duration", "200.0")
    v = run(collide, text, "event", scratch, "ten_cut")["frames/velocity"][:]
    k = (v[:, :10] ** 2).sum(axis=(1, 2)) / 2
    sys.path.insert(0, str(COURSE))
    import lab_structure
    e = lab_structure.collide_module(collide).stationary_mean(k)
    measured = [e["equilibration_cut"], len(k), k.mean(), e["mean"], e["error"]]
    values = [float(v) for v in said.groups()]
    if any(abs(v - m) > 0.006 for v, m in zip(values, measured)):
        return [f"4-validating-a-solver.md: the cut on exercise 4.4's series: the page says {values}, the run "
                f"{[round(float(m), 3) for m in measured]}"]
    return []


def structure_from_data(collide, run):
    """`lab.py structure RUN --from data`, as a student runs it: (the cut it chose, the frames from
    there, g(d), its error, |psi6|), or the failure when it prints no cut."""
    env = dict(os.environ)
    env["PATH"] = f"{pathlib.Path(collide).resolve().parent}{os.pathsep}{env['PATH']}"
    done = subprocess.run(["/usr/bin/python3", str(COURSE / "lab.py"), "structure", str(run), "--from", "data"],
                          capture_output=True, text=True, env=env)
    got = re.search(r"(\d+) frames from t = ([\d.]+) \(the cut from the data.*?g\(d\) ([\d.]+) \+- ([\d.]+).*?"
                    r"\|psi6\| ([\d.]+)", done.stdout, re.S)
    if not got:
        return f"lab.py structure {run.name} --from data printed no cut:\n{done.stdout}{done.stderr}"
    frames, cut, contact, error, psi6 = got.groups()
    return float(cut), int(frames), float(contact), float(error), float(psi6)


def periodic_gas_cut(collide, scratch, page):
    """Chapter 2.4: the cut `lab.py equilibration` takes on box_gas_1000 in a periodic box over
    60 time units, at or before the fixed cut of 10 the collision rates leave out."""
    said = re.search(r"the cut the data choose \(4\.4; `lab\.py equilibration` on box_gas_1000 with `boundary = "
                     r"\"periodic\"` and `duration = 60\.0`\) is t = ([\d.]+), so the fixed cut at 10 is after it", page)
    if not said:
        return ["2-many-disks-exactly.md: section 2.4 does not state the cut from the data of box_gas_1000"]
    scene = scratch / "box_gas_periodic.toml"
    scene.write_text(set_key(set_key((SCENES / "box_gas_1000.toml").read_text(), "boundary", '"periodic"'),
                             "duration", "60.0"))
    sys.path.insert(0, str(COURSE))
    import lab_structure
    lab_structure.collide_module(collide)   # the module beside this collide, for lab_equilibration
    import lab_equilibration
    r = lab_equilibration.cuts(scene)
    cut = r["chosen"]["equilibration_cut"] * r["window"]
    if cut > 10 or abs(float(said.group(1)) - cut) > 1e-9:
        return [f"2-many-disks-exactly.md: box_gas_1000 (periodic, 60 time units): the page says the data cut at "
                f"t = {said.group(1)}, lab.py equilibration at t = {cut:g}"]
    return []


def fact_fixed_cuts(collide, scratch):
    """Chapter 2, the fixed cuts of `lab.py structure` against the cut from the data (4.4): exercise
    2.8's fluid at eta = 0.5 (the cut the solution and the g(r) figure's caption state, at or
    before t = 20, and what the frames from it give) and exercise 2.9's crystal-shaped boxes at
    eta = 0.65 (the cuts at N = 72 and 870, before the second half, and |psi6| from them), and
    2.4's collision rates after t = 10 (periodic_gas_cut)."""
    page = re.sub(r"\s+", " ", (COURSE / "2-many-disks-exactly.md").read_text())
    caption = re.search(r"at η = 0\.5 the cut from the data, `lab\.py structure fluid\.h5 --from data` on exercise "
                        r"2\.8's run, is t = ([\d.]+), so t = 20 is after it", page)
    fluid = re.search(r"With `--from data` the run's \|Ψ₆\| series chooses t = ([\d.]+) \(4\.4\): .*? from t = ([\d.]+) "
                      r"its (\d+) frames give g\(d\) ([\d.]+) ± ([\d.]+)", page)
    boxes = re.search(r"The second half starts after the cut the data choose \(`--from data`, 4\.4\): t = ([\d.]+) at "
                      r"N = 72, .*? and t = ([\d.]+) at N = 870; from there \|Ψ₆\| is ([\d.]+) and ([\d.]+)", page)
    if not (caption and fluid and boxes):
        return ["2-many-disks-exactly.md: the cut from the data is not stated beside the fixed cuts of the g(r) "
                "figure, exercise 2.8 and exercise 2.9"]
    fluid_cut = structure_from_data(collide, fluid_run(collide, scratch / "fluid_cut.h5", "0.5", "0.25"))
    if isinstance(fluid_cut, str):
        return [fluid_cut]
    cut, frames, contact, error, _ = fluid_cut
    failures = []
    said = [float(caption.group(1)), float(fluid.group(1)), float(fluid.group(2)), int(fluid.group(3)),
            float(fluid.group(4)), float(fluid.group(5))]
    if cut > 20 or any(abs(v - m) > 0.0006 for v, m in zip(said, [cut, cut, cut, frames, contact, error])):
        failures.append(f"2-many-disks-exactly.md: the fluid at eta = 0.5 from the cut of the data: the page says "
                        f"{said}, lab.py structure --from data {[cut, cut, cut, frames, contact, error]}")
    measured = []
    for disks, duration in ((72, 2000), (870, 200)):
        out = scratch / f"n{disks}_cut.h5"
        subprocess.run([collide, "run", str(SCENES / f"physics/li2022_n{disks}_crystal.toml"), "--backend", "event",
                        "--frames", "--out", str(out), "--set", "particles.0.radius=0.42329881999845265",
                        "--set", f"run.duration={duration}"], check=True, capture_output=True)
        printed = structure_from_data(collide, out)
        if isinstance(printed, str):
            return failures + [printed]
        cut, *_, psi6 = printed
        if cut >= duration / 2:
            failures.append(f"2-many-disks-exactly.md: exercise 2.9 at N = {disks}: the data cut at t = {cut:g}, "
                            f"not before the second half")
        measured.append((cut, psi6))
    said = [float(v) for v in boxes.groups()]
    wanted = [measured[0][0], measured[1][0], measured[0][1], measured[1][1]]
    if any(abs(v - m) > 0.0006 for v, m in zip(said, wanted)):
        failures.append(f"2-many-disks-exactly.md: exercise 2.9's cuts from the data and |psi6| from them: the page "
                        f"says {said}, lab.py structure --from data {wanted}")
    return failures + periodic_gas_cut(collide, scratch, page)


def fact_metropolis_slips(collide, scratch):
    """Exercise 4.6: the wall pressure and z the checker finds for the two slips that sample legal
    configurations with the wrong measure (redrawing until legal, a window clipped to the box)."""
    page = re.sub(r"\s+", " ", (COURSE / "4-validating-a-solver.md").read_text())
    said = re.search(r"drawing again until a move is legal gives βPd² = ([\d.]+) ± ([\d.]+), (\d+) combined errors "
                     r"low .*? clipping the step's window to the box so that no move leaves it, ([\d.]+) ± ([\d.]+)", page)
    if not said:
        return ["4-validating-a-solver.md: exercise 4.6 states no wall pressure for the redrawing and clipped samplers"]
    env = dict(os.environ)
    env["PATH"] = f"{pathlib.Path(collide).resolve().parent}{os.pathsep}{env['PATH']}"
    measured = []
    for name in ("metropolis.py", "metropolis--clipped_window.py"):
        done = subprocess.run(["/usr/bin/python3", str(COURSE / "lab.py"), "check", "metropolis",
                               str(ROOT / "tests/docs/wrong_answers" / name)], capture_output=True, text=True, env=env)
        got = re.search(r"beta P d\^2 = ([\d.]+) ± ([\d.]+) .*?\(z = ([-+][\d.]+)\)", done.stdout)
        if not got:
            return [f"exercise 4.6: the checker printed no wall pressure for {name}:\n{done.stdout}{done.stderr}"]
        measured.append([float(g) for g in got.groups()])
    (redraw, redraw_error, redraw_z), (clipped, clipped_error, _) = measured
    values = [float(v) for v in said.groups()]
    wanted = [redraw, redraw_error, -redraw_z, clipped, clipped_error]
    if any(abs(v - m) > (0.6 if k == 2 else 0.0006) for k, (v, m) in enumerate(zip(values, wanted))):
        return [f"4-validating-a-solver.md: exercise 4.6's slips: the page says {values}, the checker {wanted}"]
    return []


# Each statement of the text and the function that measures it, in the order the text makes them.
# CTest runs each as its own test (Course.TextMatchesTheRuns.NAME), so a slow build (the
# sanitizers' dev preset) spreads them over its workers and times each apart.
FACTS = {
    "virial": fact_virial, "galperin": fact_galperin, "cradle": fact_cradle,
    "slope": lambda collide, scratch: fact_slope(), "reunion": fact_reunion,
    "root_rounding": lambda collide, scratch: fact_root_rounding(), "step_boundary": fact_step_boundary,
    "multi_contact": fact_multi_contact, "pairing": fact_pairing, "correlated_series": fact_correlated_series,
    "lyapunov": lambda collide, scratch: fact_lyapunov(), "wording": lambda collide, scratch: fact_wording(),
    "replicates": fact_replicates, "enskog_walls": fact_enskog_walls, "fitted_grid": fact_fitted_grid,
    "sampling": fact_sampling, "declared_exact": fact_declared_exact, "pair_correlation": fact_pair_correlation,
    "hexatic": fact_hexatic,
    "finite_size_72": functools.partial(fact_finite_size, disks_of_rows="72"),
    "finite_size_224": functools.partial(fact_finite_size, disks_of_rows="224"),
    "finite_size_870": functools.partial(fact_finite_size, disks_of_rows="870"),
    "engel_table": lambda collide, scratch: fact_engel_table(), "diffusion": fact_diffusion, "vacf": fact_vacf,
    "equilibration_cut": fact_equilibration_cut, "metropolis_slips": fact_metropolis_slips,
    "fixed_cuts": fact_fixed_cuts,
}


def check_facts(collide, names=()):
    """The statements named (all of them when none is), each measured in a scratch folder of its own."""
    unknown = [name for name in names if name not in FACTS]
    if unknown:
        return [f"no statement named {', '.join(unknown)}; the statements: {' '.join(FACTS)}"]
    failures = []
    for name in names or FACTS:
        with tempfile.TemporaryDirectory(prefix=f"collide-facts-{name}-") as scratch:
            failures += FACTS[name](collide, pathlib.Path(scratch))
    print(f"{len(names or FACTS)} statements of the text measured")
    return failures


def check_lab(collide):
    """Every coding exercise: its worked solution is accepted, its wrong answer rejected."""
    wrong_dir = ROOT / "tests/docs/wrong_answers"
    env = dict(os.environ)
    env["PATH"] = f"{pathlib.Path(collide).resolve().parent}{os.pathsep}{env['PATH']}"
    found = coding_exercises()
    failures = []
    if len(found) < MIN_CODING_EXERCISES:
        failures.append(f"{len(found)} coding exercises, at least {MIN_CODING_EXERCISES} wanted")
    pages_with = {page.name for page, _ in found.values()}
    failures += [f"{page.name}: no coding exercise (lab.py check)" for page in chapters() if page.name not in pages_with]
    lab = ROOT / "docs/course/lab.py"
    for name, (page, solution) in sorted(found.items()):
        with tempfile.TemporaryDirectory(prefix="collide-lab-") as scratch:
            right = pathlib.Path(scratch) / f"{name}.py"
            right.write_text(solution)
            done = subprocess.run(["/usr/bin/python3", str(lab), "check", name, str(right)], capture_output=True,
                                  text=True, env=env)
        if done.returncode != 0 or f"{name}: right" not in done.stdout:
            failures.append(f"{page.name}: the worked solution of '{name}' is not accepted:\n{done.stdout}{done.stderr}")
        if not (wrong_dir / f"{name}.py").exists():
            failures.append(f"'{name}' has no wrong answer in {wrong_dir} to prove its checker rejects one")
        for wrong in answers(wrong_dir, name):
            failures += judged(lab, name, wrong, "wrong", 1, env)
        for right in answers(ROOT / "tests/docs/right_answers", name):
            failures += judged(lab, name, right, "right", 0, env)
        print(f"{name}: solution and {len(answers(ROOT / 'tests/docs/right_answers', name))} other right answers "
              f"accepted, {len(answers(wrong_dir, name))} wrong answers rejected")
    return failures


def answers(folder, name):
    """NAME.py and NAME--WHAT.py: the answers to exercise NAME in folder."""
    return sorted(p for p in folder.glob(f"{name}*.py") if p.stem == name or p.stem.startswith(f"{name}--"))


def judged(lab, name, answer, verdict, status, env):
    """The checker's verdict on answer must be `verdict`, and its message must hold the answer's
    `# hint: TEXT` line if it has one (a rejection that names the wrong slip misleads)."""
    done = subprocess.run(["/usr/bin/python3", str(lab), "check", name, str(answer)], capture_output=True, text=True,
                          env=env)
    if done.returncode != status or f"{name}: {verdict}" not in done.stdout:
        return [f"the checker of '{name}' does not find {answer.name} {verdict}:\n{done.stdout}{done.stderr}"]
    hints = re.findall(r"(?m)^# hint: (.*)$", answer.read_text())
    return [f"the checker of '{name}' rejects {answer.name} without naming its slip ({hint!r}):\n{done.stdout}"
            for hint in hints if hint not in done.stdout]


def main():
    what = sys.argv[1] if len(sys.argv) > 1 else ""
    if what == "exercises" and len(sys.argv) == 3:
        failures = check_exercises(sys.argv[2])
    elif what == "links":
        failures = check_links() + check_quotes() + check_scripts_run()
    elif what == "figures" and len(sys.argv) == 3:
        failures = check_figures(sys.argv[2])
    elif what == "facts" and len(sys.argv) >= 3:
        failures = check_facts(sys.argv[2], sys.argv[3:])
    elif what == "fact-names":
        print(" ".join(FACTS))
        return 0
    elif what == "lab" and len(sys.argv) == 3:
        failures = check_lab(sys.argv[2])
    else:
        sys.exit(__doc__)
    for failure in failures:
        print(f"FAIL {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
