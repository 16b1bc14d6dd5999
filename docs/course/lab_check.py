"""Checkers of the course's coding exercises: `python3 docs/course/lab.py check EXERCISE FILE.py`.

Each exercise asks for one function in a file of the student's own. Its checker imports the
file, calls the function on cases whose answer it knows independently (an exact computation,
a published reference of data/references, or a brute-force enumeration), and prints either
"EXERCISE: right" or "EXERCISE: wrong: " with the first case that fails. The course's worked
solutions pass and a typical wrong answer of each is rejected (tests/docs/test_lab_check.py).
"""
import decimal
import importlib.util
import math
import pathlib
import tomllib

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]


class Wrong(Exception):
    """The student's function gave a wrong answer on one case."""


class Unavailable(Exception):
    """What a checker needs from the repository is not there."""


def reference(name):
    """A published reference of the repository's data/references (the checkers need a checkout)."""
    path = ROOT / "data" / "references" / name
    if not path.is_file():
        raise Unavailable(f"{path} is missing: run lab.py from a checkout of the repository")
    return tomllib.loads(path.read_text())


def load(path, function):
    spec = importlib.util.spec_from_file_location("student", path)
    if spec is None:
        raise Wrong(f"{path} is not a Python file")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    if not hasattr(module, function):
        raise Wrong(f"{path} defines no function {function}()")
    return getattr(module, function)


# --- Chapter 1: Galperin's counter ----------------------------------------------------------

def check_galperin(path):
    """count_collisions(mass_ratio) -> pair plus wall collisions, against Galperin (2003)."""
    count = load(path, "count_collisions")
    for point in reference("galperin_2003.toml")["points"][:4]:
        got = count(point["mass_ratio"])
        if got != point["collisions"]:
            raise Wrong(f"count_collisions({point['mass_ratio']:g}) = {got}, Galperin's count is "
                        f"{point['collisions']} (pair and wall collisions together)")
    return "314 collisions at mass ratio 100^2, 3141 at 100^3"


# --- Chapter 2: the stable root -------------------------------------------------------------

def exact_contact_time(dx, dy, ux, uy, sigma):
    """The first root of (u.u) t^2 + 2 b t + c = 0, with b, c and u.u rounded to doubles as a
    program computes them and the root then solved in 60-digit decimals, or None if there is
    none. So the check measures the error of the root formula alone, not the rounding of c."""
    b = dx * ux + dy * uy
    c = dx * dx + dy * dy - sigma * sigma
    uu = ux * ux + uy * uy
    decimal.getcontext().prec = 60
    b, c, uu = decimal.Decimal(b), decimal.Decimal(c), decimal.Decimal(uu)
    disc = b * b - uu * c
    if b >= 0 or c <= 0 or disc <= 0:
        return None
    return float(c / (-b + disc.sqrt()))


def root_cases():
    rng = np.random.default_rng(7)
    cases = [(-1.0 - 1e-12, 0.0, 1.0, 0.0, 1.0),        # head-on, a gap of 1e-12
             (-1.0 - 1e-10, 1e-3, 3.0, 0.0, 1.0),       # nearly touching, slightly off centre
             (-(1 + 1e-9), 0.0, 50.0, 0.3, 1.0)]        # fast and nearly touching
    for _ in range(40):
        angle, gap = rng.uniform(0, 2 * np.pi), 10.0 ** rng.uniform(-13, 0)
        d = (1 + gap) * np.array([np.cos(angle), np.sin(angle)])
        u = -d * rng.uniform(0.1, 10) + rng.normal(0, 0.5, 2)
        cases.append((d[0], d[1], u[0], u[1], 1.0))
    cases.append((2.0, 0.0, 1.0, 0.0, 1.0))             # moving apart: never
    cases.append((0.0, 3.0, 1.0, 0.0, 1.0))             # paths that do not meet: never
    return cases


def check_root(path):
    """collision_time(dx, dy, ux, uy, sigma) -> first contact time, or None."""
    time = load(path, "collision_time")
    worst = 0.0
    for case in root_cases():
        exact, got = exact_contact_time(*case), time(*case)
        if exact is None:
            if got is not None and math.isfinite(got):
                raise Wrong(f"collision_time{case} = {got}, but these disks never touch (None expected)")
            continue
        if got is None:
            raise Wrong(f"collision_time{case} = None, but they touch at t = {exact:.17g}")
        error = abs(got - exact) / exact
        worst = max(worst, error)
        if error > 1e-12:
            raise Wrong(f"collision_time{case} = {got:.17g}, exact {exact:.17g}: relative error "
                        f"{error:.1e} (a nearly touching pair needs the cancellation-free form)")
    return f"largest relative error {worst:.1e} over {len(root_cases())} pairs"


# --- Chapter 2: Haff's law ------------------------------------------------------------------

def check_haff(path):
    """haff_tau(t, T) -> tau of T(t) = T0 / (1 + t/tau)^2, fitted to noisy data."""
    fit = load(path, "haff_tau")
    rng = np.random.default_rng(3)
    for tau, T0 in ((12.0, 1.0), (4.0, 2.5), (40.0, 0.5)):
        t = np.linspace(0, 2 * tau, 41)
        T = T0 / (1 + t / tau) ** 2 * (1 + rng.normal(0, 0.003, t.size))
        got = float(fit(t, T))
        if not abs(got - tau) < 0.03 * tau:
            raise Wrong(f"haff_tau on T0 = {T0}, tau = {tau} (0.3 % noise) gave {got:.4g}")
    return "tau within 3 % on three noisy cooling curves"


# --- Chapter 3: tunnelling --------------------------------------------------------------------

def step_detects(gap, speed, dt, sigma):
    """Brute force: does any step end with the centres closer than sigma?"""
    k = np.arange(1, int((gap + sigma) / (speed * dt)) + 2)
    return bool(np.any(np.abs(gap - k * speed * dt) < sigma))


def check_tunnel(path):
    """detected(gap, speed, dt, sigma) -> whether a stepped rule sees the contact."""
    detected = load(path, "detected")
    rng = np.random.default_rng(11)
    cases = [(4.9, 150.0, 2.5e-3, 0.3), (4.9, 150.0, 5e-3, 0.3)]  # exercise 3.1's scene
    while len(cases) < 200:
        sigma, speed, dt = rng.uniform(0.1, 1), rng.uniform(1, 200), 10 ** rng.uniform(-4, -1.5)
        gap = sigma + rng.uniform(0, 5)
        positions = np.abs(gap - np.arange(1, 2000) * speed * dt)
        if np.min(np.abs(positions - sigma)) > 1e-6:   # no step ends on the window's edge
            cases.append((gap, speed, dt, sigma))
    for case in cases:
        if bool(detected(*case)) != step_detects(*case):
            raise Wrong(f"detected{case} = {bool(detected(*case))}, but the steps "
                        f"{'do' if step_detects(*case) else 'do not'} end inside the window")
    return f"{len(cases)} cases, including steps longer than the window that still land in it"


# --- Chapter 4: block averaging -------------------------------------------------------------

def reference_block_error(x, block):
    n = len(x) // block
    means = np.asarray(x[:n * block]).reshape(n, block).mean(axis=1)
    return means.std(ddof=1) / math.sqrt(n)


def check_blocks(path):
    """block_standard_error(x, block) -> standard error of the mean from block means."""
    se = load(path, "block_standard_error")
    rng = np.random.default_rng(5)
    x = np.empty(20011)
    x[0] = 0.0
    noise = rng.normal(size=x.size)
    for i in range(1, x.size):                          # AR(1): correlation time about 20 samples
        x[i] = 0.95 * x[i - 1] + noise[i]
    for block in (1, 50, 400, 1000):
        got, want = float(se(x, block)), reference_block_error(x, block)
        if not abs(got - want) <= 1e-9 * want:
            raise Wrong(f"block_standard_error(x, {block}) = {got:.6g}, expected {want:.6g} (means of "
                        f"{len(x) // block} whole blocks, the incomplete last one dropped)")
    return (f"naive {reference_block_error(x, 1):.3g} against {reference_block_error(x, 400):.3g} "
            "from blocks of 400 on a correlated series")


# --- Chapter 5: counting sort ---------------------------------------------------------------

def reference_counting_sort(cell, n_cells):
    start = np.zeros(n_cells + 1, dtype=int)
    np.add.at(start, np.asarray(cell) + 1, 1)
    start = np.cumsum(start)
    return list(start), list(np.argsort(cell, kind="stable"))


def check_counting_sort(path):
    """counting_sort(cell, n_cells) -> (start, order) as core/uniform_grid.h builds them."""
    sort = load(path, "counting_sort")
    rng = np.random.default_rng(2)
    for n_cells, n in ((1, 5), (9, 40), (100, 1000), (64, 3)):
        cell = [int(c) for c in rng.integers(0, n_cells, n)]
        start, order = sort(cell, n_cells)
        want_start, want_order = reference_counting_sort(cell, n_cells)
        if [int(s) for s in start] != want_start:
            raise Wrong(f"{n_cells} cells, {n} disks: start = {list(start)[:12]}..., expected "
                        f"{want_start[:12]}... (n_cells + 1 offsets, disks of cell c at start[c]..start[c+1])")
        if [int(i) for i in order] != [int(i) for i in want_order]:
            raise Wrong(f"{n_cells} cells, {n} disks: order = {list(order)[:12]}..., expected "
                        f"{[int(i) for i in want_order[:12]]}... (within a cell, disks in index order)")
    return "offsets and order match on four grids"


EXERCISES = {"galperin": check_galperin, "root": check_root, "haff": check_haff, "tunnel": check_tunnel,
             "blocks": check_blocks, "counting_sort": check_counting_sort}


def check(exercise, path):
    """Prints the verdict; returns the exit status (0 right, 1 wrong, 2 unknown exercise)."""
    if exercise not in EXERCISES:
        print(f"lab.py check: no exercise {exercise!r}; the exercises are {', '.join(EXERCISES)}")
        return 2
    if not pathlib.Path(path).is_file():
        print(f"lab.py check: {path}: no such file")
        return 2
    try:
        detail = EXERCISES[exercise](path)
    except Unavailable as e:
        print(f"lab.py check: {e}")
        return 2
    except Wrong as e:
        print(f"{exercise}: wrong: {e}")
        return 1
    except Exception as e:  # the student's code raised: say where, without a traceback wall
        print(f"{exercise}: wrong: {path} raised {type(e).__name__}: {e}")
        return 1
    print(f"{exercise}: right ({detail})")
    return 0
