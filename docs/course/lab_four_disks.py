"""The checker of exercise 4.6 (`lab.py check metropolis FILE.py`): a student's Metropolis
sampler held to exact dynamics in the four-disk box.

The box: four disks of radius 0.15 in a unit square with hard walls, the teaching system of
Krauth's "Statistical Mechanics: Algorithms and Computations" (2006, ch. 2: markov_disks_box,
event_disks_box) and of Li, Nishikawa, Hoellmer, Carillo, Maggs and Krauth, J. Chem. Phys. 157,
234111 (2022) (their HistoricDisks repository, Python/four-disk: Metropolis_disks_box.py samples
it, fitting.py measures its pressure). The smallest system in which molecular dynamics and
sampling must agree; tests/conformance/test_four_disk_box.cpp holds collide's solvers and
samplers to each other there.

One quantity, two routes (docs/monte-carlo.md, "Walls"):
  - the wall pressure from the student's configurations: the contact theorem for a hard wall,
    beta F = the number of centres per unit distance from the walls at contact (distance r),
    summed over the four walls (Li et al.'s eq. (12)). The (disk, wall) gaps, distance to the
    wall minus r, are counted in bins over [0, WINDOW) and their density extrapolated to gap 0
    by a least-squares parabola (a fit linear in the counts, so each configuration gets its own
    value and the series is averaged as every recorded pressure is: collide.stationary_mean,
    the equilibration cut from the data and batch means);
  - `event`'s momentum given to the walls per unit time over kT = K / N (core/thermo: with
    walls the N disks have 2N degrees of freedom, K = N kT), in windows of WINDOW_TIME, the
    same estimate of the mean and its error.
Both as beta P d^2 = beta F / perimeter * d^2, Li et al.'s beta P (2 sigma)^2.
"""
import pathlib

import numpy as np

from lab_check import Wrong, load
from lab_structure import collide

RADIUS, SIDE, DELTA = 0.15, 1.0, 0.1     # Li et al.'s box and step (Metropolis_disks_box.py)
START = np.array([[0.25, 0.25], [0.75, 0.25], [0.25, 0.75], [0.75, 0.75]])
SWEEPS, WARM_UP = 50_000, 200            # configurations measured (one a sweep), sweeps before
WINDOW, BINS = 0.1, 20                   # the gap histogram: [0, r / 1.5) in 20 bins, a parabola
EVENT_TIME, WINDOW_TIME = 20_000.0, 10.0  # exact dynamics: its run and its windows
SEED = 11
# A z beyond this rejects: a right sampler falls outside it about once in 16 000 checks.
MOST_Z = 4.0

# The box, one scene file shared with the C++ conformance test (tests/conformance/test_four_disk_box.cpp).
FOUR_DISK_SCENE = pathlib.Path(__file__).resolve().parents[2] / "data" / "scenes" / "physics" / "four_disk_box.toml"


def per_length_d2():
    """beta F (summed over the walls) -> beta P d^2: over the perimeter, times d^2."""
    return (2 * RADIUS) ** 2 / (4 * SIDE)


def event_wall_pressure():
    """`event`'s beta P d^2 in the four-disk box, from the momentum given to the walls in windows of
    WINDOW_TIME over EVENT_TIME: collide.stationary_mean of the series (mean, error)."""
    c = collide()
    sim = c.Simulation(c.Scene.from_file(str(FOUR_DISK_SCENE)), "event")
    kt = sim.metrics()["kinetic_energy"] / len(sim)   # conserved: e = 1, elastic walls
    series, before = [], 0.0
    for k in range(1, int(EVENT_TIME / WINDOW_TIME) + 1):
        sim.advance_to(k * WINDOW_TIME)
        impulse = sim.stats()["counters"]["wall_impulse"]
        series.append((impulse - before) / (WINDOW_TIME * kt) * per_length_d2())
        before = impulse
    e = c.stationary_mean(np.array(series))
    return e["mean"], e["error"]


def extrapolation_weights():
    """w_k such that sum_k w_k y_k is the least-squares parabola through the bin densities y_k
    (bin centres in [0, WINDOW)) at gap 0."""
    width = WINDOW / BINS
    centres = (np.arange(BINS) + 0.5) * width
    design = np.vander(centres, 3, increasing=True)          # 1, s, s^2
    return np.linalg.pinv(design)[0] / width                  # the row for the value at s = 0, per count


def sampled_wall_pressure(configurations):
    """beta P d^2 from configurations (F x 4 x 2): each configuration's extrapolated density of
    (disk, wall) gaps at contact, as a series, through collide.stationary_mean (mean, error)."""
    gaps = np.concatenate([configurations - RADIUS, SIDE - RADIUS - configurations], axis=2).reshape(len(configurations), -1)
    weights = np.append(extrapolation_weights(), 0.0)        # gaps beyond the window weigh nothing
    bins = np.where((gaps >= 0) & (gaps < WINDOW), (gaps / WINDOW * BINS).astype(int).clip(0, BINS - 1), BINS)
    series = weights[bins].sum(axis=1) * per_length_d2()
    e = collide().stationary_mean(series)
    return e["mean"], e["error"]


def sample(sweep):
    """SWEEPS configurations of the four-disk box, one after each sweep, after WARM_UP sweeps."""
    rng = np.random.default_rng(SEED)
    x = START.copy()
    configurations = np.empty((SWEEPS, len(x), 2))
    for k in range(WARM_UP + SWEEPS):
        accepted = sweep(x, RADIUS, SIDE, DELTA, rng)
        if not 0 <= int(accepted) <= len(x):
            raise Wrong(f"sweep {k}: {accepted} moves accepted out of {len(x)} trials")
        if k >= WARM_UP:
            configurations[k - WARM_UP] = x
    return configurations


def check_legal(configurations):
    """Every centre at least RADIUS from every wall, every pair at least 2 RADIUS apart."""
    slack = 1e-12
    inside = (configurations >= RADIUS - slack) & (configurations <= SIDE - RADIUS + slack)
    if not inside.all():
        k, i, _ = np.argwhere(~inside)[0]
        raise Wrong(f"after sweep {WARM_UP + k + 1}, disk {i} at ({configurations[k, i, 0]:.4f}, {configurations[k, i, 1]:.4f}) is "
                    f"closer than its radius {RADIUS} to a wall: a disk must stay at least one radius from every "
                    "wall (a centre in [r, L - r] on each axis), else the move is rejected")
    d = configurations[:, :, None, :] - configurations[:, None, :, :]
    r = np.hypot(d[..., 0], d[..., 1])
    r[:, np.arange(4), np.arange(4)] = np.inf
    if r.min() < 2 * RADIUS * (1 - slack):
        k = int(np.argmin(r.min(axis=(1, 2))))
        raise Wrong(f"after sweep {WARM_UP + k + 1} two disks overlap (centres {r[k].min():.4f} apart, less than the diameter "
                    f"{2 * RADIUS}): a move that brings the disk closer than a diameter to any other is rejected")
    if np.ptp(configurations, axis=0).max() == 0:
        raise Wrong("the disks never moved: keep a legal move (x[i] = new)")


def check_metropolis(path):
    """metropolis_sweep(x, radius, side, delta, rng) -> moves accepted; one sweep (N trial moves)
    on the centres x (N x 2) of equal disks of `radius` in the square [0, side]^2 with walls, in
    place. Checked on the four-disk box: every configuration of 50 000 sweeps legal, and the wall
    pressure from them within four combined errors of exact dynamics' (`event`)."""
    sweep = load(path, "metropolis_sweep")
    configurations = sample(sweep)
    check_legal(configurations)
    (mc, mc_error), (md, md_error) = sampled_wall_pressure(configurations), event_wall_pressure()
    z = (mc - md) / np.hypot(mc_error, md_error)
    said = (f"wall pressure beta P d^2 = {mc:.4f} ± {mc_error:.4f} from {SWEEPS} sweeps against `event`'s "
            f"{md:.4f} ± {md_error:.4f} (z = {z:+.1f})")
    if abs(z) > MOST_Z:
        raise Wrong(f"four disks of radius {RADIUS} in a unit square: {said}. The configurations are legal but not "
                    "uniformly sampled: is the proposal symmetric (a step uniform in [-delta, delta]^2 whatever the "
                    "position; a move out of the box rejected, not redrawn or clipped to the box), and does a "
                    "rejected move keep the old configuration, counted again as the chain's next sample?")
    return said
