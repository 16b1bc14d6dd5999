"""Checkers of the course's coding exercises: `python3 docs/course/lab.py check EXERCISE FILE.py`.

Each exercise asks for one function in a file of the student's own. Its checker imports the
file, calls the function on cases whose answer it knows independently (an exact computation,
a published reference of data/references, or a brute-force enumeration), and prints either
"EXERCISE: right" or "EXERCISE: wrong: " with the first case that fails. The course's worked
solutions pass, typical wrong answers are rejected with a hint that names their slip, and
other right answers (an exact root, an exact count) pass (tests/docs/check_course.py lab).
"""
import decimal
import importlib.util
import math
import pathlib
import time
import tomllib
from fractions import Fraction

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

def exact_collision_count(mass_ratio):
    """Pair plus wall collisions of the light disk (mass 1, at rest) struck by the heavy one
    (mass_ratio, speed -1), simulated in rational arithmetic: no rounding can miscount."""
    m, M = Fraction(1), Fraction(mass_ratio)
    v, V, count = Fraction(0), Fraction(-1), 0
    while True:
        if V < v:                      # the heavy disk catches the light one: a pair collision
            v, V = ((m - M) * v + 2 * M * V) / (m + M), ((M - m) * V + 2 * m * v) / (m + M)
        elif v < 0:                    # the light disk flies into the wall
            v = -v
        else:
            return count
        count += 1


def check_galperin(path):
    """count_collisions(mass_ratio) -> pair plus wall collisions, against Galperin (2003) at the
    powers of 100 and against an exact count at mass ratios whose count is no digit string of
    pi (at 2 the count is 5, while int(pi sqrt 2) = 4)."""
    count = load(path, "count_collisions")
    cases = [(ratio, exact_collision_count(ratio)) for ratio in (2, 3, 5, 10, 50)]
    cases += [(p["mass_ratio"], p["collisions"]) for p in reference("galperin_2003.toml")["points"][:4]]
    for ratio, want in cases:
        got = count(ratio)
        if got != want:
            raise Wrong(f"count_collisions({ratio:g}) = {got}, the count is {want} (pair and wall collisions "
                        "together; pi's digits appear only at mass ratios 100^k)")
    return "5 collisions at mass ratio 2, 314 at 100^2, 3141 at 100^3"


# --- Chapter 2: the stable root -------------------------------------------------------------

def decimal_root(b, c, uu):
    """The first root of uu t^2 + 2 b t + c = 0 in 60-digit decimals, or None if there is none."""
    decimal.getcontext().prec = 60
    disc = b * b - uu * c
    if b >= 0 or c <= 0 or disc <= 0:
        return None
    return float(c / (-b + disc.sqrt()))


def exact_contact_time(dx, dy, ux, uy, sigma):
    """The exact first contact of the given doubles: b, c and u.u formed in 60-digit decimals."""
    dx, dy, ux, uy, sigma = (decimal.Decimal(v) for v in (dx, dy, ux, uy, sigma))
    decimal.getcontext().prec = 60
    return decimal_root(dx * ux + dy * uy, dx * dx + dy * dy - sigma * sigma, ux * ux + uy * uy)


def rounded_coefficient_root(dx, dy, ux, uy, sigma):
    """The exact root of the coefficients b, c, u.u as a double program rounds them. Near contact
    c = d.d - sigma^2 cancels and keeps only about log10(c / (eps d.d)) digits, so this root and
    the exact one differ by about eps d.d / c relative (1e-10 at a gap of 1e-6): a program's root
    formula can do no better than this one, however it solves the quadratic."""
    b = dx * ux + dy * uy
    c = dx * dx + dy * dy - sigma * sigma
    uu = ux * ux + uy * uy
    return decimal_root(*(decimal.Decimal(v) for v in (b, c, uu)))


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
    """Accepted: within 1e-12 of the exact root of the given doubles, or of the root of the
    coefficients as rounded in double (the most a double-precision formula can reach)."""
    time = load(path, "collision_time")
    worst = 0.0
    for case in root_cases():
        exact, rounded, got = exact_contact_time(*case), rounded_coefficient_root(*case), time(*case)
        if exact is None:
            if got is not None and math.isfinite(got):
                raise Wrong(f"collision_time{case} = {got}, but these disks never touch (None expected)")
            continue
        if got is None:
            raise Wrong(f"collision_time{case} = None, but they touch at t = {exact:.17g}")
        error = min(abs(got - exact) / exact, abs(got - rounded) / rounded)
        worst = max(worst, error)
        if error > 1e-12:
            raise Wrong(f"collision_time{case} = {got:.17g}: relative error {abs(got - exact) / exact:.1e} "
                        f"from the exact root {exact:.17g} and {abs(got - rounded) / rounded:.1e} from "
                        f"the root of the rounded coefficients {rounded:.17g}: more than rounding c "
                        "explains, the cancellation of -b - sqrt(D) (use c / (-b + sqrt(D)))")
    return (f"largest relative error {worst:.1e} over {len(root_cases())} pairs, from the exact root "
            "or the root of the rounded coefficients")


# --- Chapter 2: Haff's law ------------------------------------------------------------------

def check_haff(path):
    """haff_tau(t, T) -> tau of T(t) = T0 / (1 + t/tau)^2, fitted to noisy data."""
    """Windows from t = 0 to 2 tau, to 20 tau (where T falls 441-fold and Haff's power law and
    any exponential part by far) and one that starts late, at 5 tau, with T0 unknown there: a
    fit of the wrong law cannot pass by matching the curve's start."""
    fit = load(path, "haff_tau")
    rng = np.random.default_rng(3)
    for tau, T0, start, end in ((10.0, 1.0, 0, 20), (25.0, 3.0, 5, 25), (12.0, 1.0, 0, 2),
                                (4.0, 2.5, 0, 2), (40.0, 0.5, 0, 2)):
        t = np.linspace(start * tau, end * tau, 41)
        T = T0 / (1 + t / tau) ** 2 * (1 + rng.normal(0, 0.003, t.size))
        got = float(fit(t, T))
        if not abs(got - tau) < 0.03 * tau:
            raise Wrong(f"haff_tau on T0 = {T0}, tau = {tau}, t from {start * tau:g} to {end * tau:g} (0.3 % "
                        f"noise) gave {got:.4g}: is the fitted law T0 / (1 + t/tau)^2?")
    return "tau within 3 % on five noisy cooling curves, windows up to 20 tau and one starting at 5 tau"


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


def block_hint(x, block, got):
    """The slip that explains a wrong standard error, where one does."""
    n = len(x) // block
    means = np.asarray(x[:n * block]).reshape(n, block).mean(axis=1)
    if abs(got - means.std(ddof=0) / math.sqrt(n)) <= 1e-9 * got:
        return (f"the spread of the {n} block means taken with ddof = 0; the sample standard deviation "
                "that estimates it needs ddof = 1 (divide by n - 1)")
    n_all = -(-len(x) // block)
    with_last = np.array([np.mean(x[i * block:(i + 1) * block]) for i in range(n_all)])
    if n_all != n and abs(got - with_last.std(ddof=1) / math.sqrt(n_all)) <= 1e-9 * got:
        return "the incomplete last block is included; use the whole blocks only"
    return f"means of {n} whole blocks (the incomplete last one dropped), their std with ddof = 1, over sqrt({n})"


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
            raise Wrong(f"block_standard_error(x, {block}) = {got:.6g}, expected {want:.6g}: "
                        f"{block_hint(x, block, got)}")
    return (f"naive {reference_block_error(x, 1):.3g} against {reference_block_error(x, 400):.3g} "
            "from blocks of 400 on a correlated series")


# --- Chapter 4: a Metropolis sampler --------------------------------------------------------

def check_metropolis(path):
    """metropolis_sweep(x, radius, side, delta, rng), held to `event` in the four-disk box (lab_four_disks.py)."""
    import lab_four_disks  # (imported here: it loads collide's module and imports this module's Wrong)
    return lab_four_disks.check_metropolis(path)


# --- Chapter 5: counting sort ---------------------------------------------------------------

def reference_counting_sort(cell, n_cells):
    start = np.zeros(n_cells + 1, dtype=int)
    np.add.at(start, np.asarray(cell) + 1, 1)
    start = np.cumsum(start)
    return list(start), list(np.argsort(cell, kind="stable"))


class Cell(int):
    """A cell index that counts how often it is compared with another: a counting sort only
    indexes with cells (O(N + cells) work), a comparison sort compares them O(N log N) times."""
    comparisons = 0

    def _count(self, other, result):
        Cell.comparisons += 1
        return result

    def __lt__(self, other): return self._count(other, int(self) < int(other))
    def __le__(self, other): return self._count(other, int(self) <= int(other))
    def __gt__(self, other): return self._count(other, int(self) > int(other))
    def __ge__(self, other): return self._count(other, int(self) >= int(other))


def check_counting_sort(path):
    """counting_sort(cell, n_cells) -> (start, order) as core/uniform_grid.h builds them: right
    offsets, a stable order, and on a large input a counting sort's work, O(N + cells): no more
    comparisons of cells than disks, and a grid of 10^6 cells for 10 disks in under a second."""
    sort = load(path, "counting_sort")
    rng = np.random.default_rng(2)
    for n_cells, n in ((1, 5), (9, 40), (100, 1000), (64, 3), (5000, 100000)):
        cell = [Cell(c) for c in rng.integers(0, n_cells, n)]
        Cell.comparisons = 0
        start, order = sort(cell, n_cells)
        want_start, want_order = reference_counting_sort(cell, n_cells)
        if [int(s) for s in start] != want_start:
            raise Wrong(f"{n_cells} cells, {n} disks: start = {list(start)[:12]}..., expected "
                        f"{want_start[:12]}... (n_cells + 1 offsets, disks of cell c at start[c]..start[c+1])")
        if [int(i) for i in order] != [int(i) for i in want_order]:
            raise Wrong(f"{n_cells} cells, {n} disks: order = {list(order)[:12]}..., expected "
                        f"{[int(i) for i in want_order[:12]]}... (within a cell, disks in index order)")
        if Cell.comparisons > n:
            raise Wrong(f"{n_cells} cells, {n} disks: the cells were compared {Cell.comparisons} times, a "
                        "comparison sort (O(N log N)); a counting sort counts disks per cell and never compares")
    few_disks_many_cells = ([3, 999_999, 0, 3, 17, 500_000, 3, 42, 0, 1], 1_000_000)
    theirs, ours = seconds(sort, *few_disks_many_cells), seconds(three_pass_sort, *few_disks_many_cells)
    if theirs > 50 * ours:   # relative to a plain-Python O(N + cells) sort: fair on a busy machine
        raise Wrong(f"10 disks on 10^6 cells took {theirs:.2g} s, {theirs / ours:.0f} times a three-pass "
                    "counting sort: the work should be O(N + cells)")
    return "offsets and a stable order on five grids, no comparisons of cells, O(N + cells) on 10^6 cells"


def seconds(function, *arguments):
    began = time.perf_counter()
    function(*arguments)
    return time.perf_counter() - began


def three_pass_sort(cell, n_cells):
    """The checker's own counting sort in plain Python, the yardstick of the timing."""
    start = [0] * (n_cells + 1)
    for c in cell:
        start[c + 1] += 1
    for c in range(n_cells):
        start[c + 1] += start[c]
    order, fill = [0] * len(cell), start[:-1]
    for i, c in enumerate(cell):
        order[fill[c]] = i
        fill[c] += 1
    return start, order


# --- Chapter 2: a whole event loop ------------------------------------------------------------

def check_event_loop(path):
    """class EventLoop, an event-driven solver held to exact dynamics (lab_event_loop.py)."""
    import lab_event_loop  # (imported here: it runs collide and imports this module's Wrong)
    return lab_event_loop.check_event_loop(path)


# --- Chapter 2: the pair correlation g(r) ----------------------------------------------------

def check_gofr(path):
    """pair_correlation(x, box, sigma, width, bins), held to collide's g(r) (lab_structure.py)."""
    import lab_structure  # (imported here: it loads collide's module and imports this module's Wrong)
    return lab_structure.check_gofr(path)


# --- Chapter 2: the diffusion coefficient by Green-Kubo ---------------------------------------

def check_green_kubo(path):
    """green_kubo(v, dt, t_max), held to the course's own Green-Kubo integral (lab_structure.py)."""
    import lab_structure  # (imported here: it imports this module's Wrong)
    return lab_structure.check_green_kubo(path)


EXERCISES = {"galperin": check_galperin, "root": check_root, "haff": check_haff, "tunnel": check_tunnel,
             "blocks": check_blocks, "metropolis": check_metropolis, "counting_sort": check_counting_sort,
             "event_loop": check_event_loop, "gofr": check_gofr,
             "green_kubo": check_green_kubo}


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
