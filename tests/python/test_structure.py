# collide.pair_correlation, local_psi6 and psi6 (python/structure.cpp over core/structure):
# values known by hand (one pair in one bin, through the periodic boundary; a perfect hexagonal
# lattice and its turn), a stack of frames equal to the frames added one by one, and refusals.
import math

import numpy as np
import pytest

import collide

PERIODIC_BOX = """description = "an empty periodic 10 x 10 box"
seed = 1
[world]
box = [0.0, 0.0, 10.0, 10.0]
boundary = "periodic"
[run]
duration = 1.0
output_interval = 1.0
dt = 1e-3
[[particles]]
kind = "list"
disks = [{ x = 1.0, y = 1.0, vx = 0.0, vy = 0.0, radius = 0.5, mass = 1.0 }]
"""


@pytest.fixture
def box():
    return collide.Scene.from_toml(PERIODIC_BOX)


def ideal_pairs(n, r1, r2, area=100.0):
    """The pairs an ideal gas of n points in `area` puts at distances in [r1, r2)."""
    return n * (n - 1) / 2 * math.pi * (r2 * r2 - r1 * r1) / area


def test_one_pair_through_the_periodic_boundary_fills_its_bin(box):
    # Centres 9.02 apart in the box, 0.98 apart through the boundary (minimum image): with
    # d = 0.9, width 0.1 and 2 bins, the pair sits in the second bin, [0.95, 1.0).
    g = collide.pair_correlation(box, np.array([[0.2, 5.0], [9.22, 5.0]]), diameter=0.9, width=0.1, bins=2)
    assert g["configurations"] == 1
    assert np.allclose(g["r"], [0.925, 0.975])
    assert g["g"][0] == 0
    assert g["g"][1] == pytest.approx(1 / ideal_pairs(2, 0.95, 1.0), rel=1e-12)


def test_a_stack_of_frames_is_the_frames_added_together(box):
    rng = np.random.default_rng(3)
    frames = rng.uniform(0, 10, (5, 40, 2))
    stacked = collide.pair_correlation(box, frames, diameter=1.0, width=0.5, bins=5)
    counts = sum(collide.pair_correlation(box, f, diameter=1.0, width=0.5, bins=5)["g"] for f in frames)
    assert stacked["configurations"] == 5
    assert np.allclose(stacked["g"], counts / 5, rtol=1e-12)
    eta = 40 * math.pi / 4 / 100
    assert stacked["compressibility"] == pytest.approx(1 + 2 * eta * stacked["contact"], rel=1e-12)


def hexagonal_lattice(columns, rows, spacing, angle=0.0):
    """Centres of a hexagonal lattice turned by `angle` (not wrapped: no box needed)."""
    x = np.array([[(c + 0.5 * (r % 2)) * spacing, r * spacing * math.sqrt(3) / 2]
                  for r in range(rows) for c in range(columns)])
    turn = np.array([[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]])
    return x @ turn.T


def test_psi6_of_a_hexagonal_lattice_that_fills_a_periodic_box_is_one():
    scene = collide.Scene.from_toml(PERIODIC_BOX.replace("[0.0, 0.0, 10.0, 10.0]",
                                                         f"[0.0, 0.0, 10.0, {10 * math.sqrt(3) / 2!r}]"))
    x = hexagonal_lattice(10, 10, 1.0) + [0.25, 0.2]
    local = collide.local_psi6(scene, x, cutoff=1.4)
    assert local.dtype == np.complex128 and local.shape == (100,)
    assert np.allclose(local, 1, atol=1e-12)           # every disk: six neighbours at 0, 60, ... degrees
    assert collide.psi6(scene, x, cutoff=1.4) == pytest.approx(1, abs=1e-12)


def test_psi6_turns_by_six_times_the_lattice(box):
    # Far from the box's edges (reflecting walls: no images), a turned patch: the interior disks'
    # local psi6 is exp(6 i alpha).
    scene = collide.Scene.from_toml(PERIODIC_BOX.replace('"periodic"', '"reflect"'))
    alpha = 0.1
    x = hexagonal_lattice(5, 5, 1.0, alpha) + [3.0, 3.0]
    local = collide.local_psi6(scene, x, cutoff=1.4)
    interior = 12  # row 2, column 2: six neighbours
    assert local[interior] == pytest.approx(np.exp(6j * alpha), abs=1e-12)
    assert collide.psi6(scene, x, cutoff=1.4) == pytest.approx(local.mean(), abs=1e-15)


@pytest.mark.parametrize("call, words", [
    (lambda s: collide.pair_correlation(s, np.array([[0.0, 0.0], [np.nan, 1.0]]), 1.0, 0.1, 5), "disk 1"),
    (lambda s: collide.pair_correlation(s, np.zeros((3, 3)), 1.0, 0.1, 5), "2 coordinates"),
    (lambda s: collide.pair_correlation(s, np.zeros((0, 3, 2)), 1.0, 0.1, 5), "no configurations"),
    (lambda s: collide.pair_correlation(s, np.zeros((2, 2)), 1.0, float("inf"), 5), "width"),
    (lambda s: collide.pair_correlation(s, np.zeros((2, 2)), 1.0, 0.1, 10**7), "bins"),
    (lambda s: collide.pair_correlation(s, np.zeros((2, 2)), 1.0, 4.5, 10), "half the shorter side"),
    (lambda s: collide.psi6(s, np.zeros((2, 2)), -1.0), "cutoff"),
    (lambda s: collide.local_psi6(s, np.zeros((2, 2, 2)), 1.4), "one configuration"),
])
def test_refusals_name_what_is_wrong(box, call, words):
    with pytest.raises(ValueError, match=words):
        call(box)
