"""docs/tools/lyapunov.py: its tangent map through a collision is the derivative of the exact
collision, checked against the difference of two exactly computed nearby trajectories."""
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "docs" / "tools"))
import lyapunov  # noqa: E402

BOX = 1000.0  # far larger than the pair: no image interferes


def collide_exactly(x, v, until):
    """Flies the pair to its collision, applies the elastic rule, flies on to `until`."""
    x, v = x.copy(), v.copy()
    t_c = lyapunov.pair_times(x, v, 0, BOX)[1]
    assert t_c < until
    x += v * t_c
    n = (x[0] - x[1]) / np.linalg.norm(x[0] - x[1])
    un = (v[0] - v[1]) @ n
    v[0] -= un * n
    v[1] += un * n
    return x + v * (until - t_c), v, t_c


def test_tangent_map_is_the_derivative_of_the_collision():
    rng = np.random.default_rng(4)
    x = np.array([[500.0, 500.0], [503.0, 500.6]])
    v = np.array([[1.0, 0.1], [-0.8, -0.2]])
    dx, dv = rng.normal(size=(2, 2)), rng.normal(size=(2, 2))
    until, eps = 4.0, 1e-7
    x1, v1, t_c = collide_exactly(x, v, until)
    x2, v2, _ = collide_exactly(x + eps * dx, v + eps * dv, until)
    # The tangent vector: free flight to the unperturbed contact, the map, free flight on.
    tx, tv = dx + dv * t_c, dv.copy()
    at_contact, vel = x + v * t_c, v.copy()
    lyapunov.tangent_collision(0, 1, at_contact, vel, tx, tv, BOX)
    tx += tv * (until - t_c)
    np.testing.assert_allclose((x2 - x1) / eps, tx, atol=1e-5)
    np.testing.assert_allclose((v2 - v1) / eps, tv, atol=1e-5)


def test_a_dilute_gas_has_a_positive_exponent_near_its_collision_rate():
    lam, rate = lyapunov.exponent(16, 0.2, duration=6.0, transient=2.0, seed=1)
    assert 0.5 * rate < lam < 3 * rate
