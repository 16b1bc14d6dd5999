#!/usr/bin/env python3
"""The largest Lyapunov exponent of a hard-disk gas, measured by tangent dynamics.

    python3 docs/tools/lyapunov.py [--disks 100] [--density 0.4] [--seeds 5] [--time 40]

Chapter 2.5 fits e^{lambda t} to the distance between two runs; that is one noisy sample. This
script follows instead a tangent vector (dx_i, dv_i of every disk) along the exact trajectory,
as G. Benettin et al. (Meccanica 15 (1980) 9) do for smooth flows and C. Dellago, H. A. Posch
and W. G. Hoover (Phys. Rev. E 53 (1996) 1485) for hard disks: between collisions dx += dv t;
at a collision of i and j (unit normal n from j to i, relative velocity v, contact distance
sigma) the perturbed pair collides dtau = -(n.dr)/(n.v) later (dr = dx_i - dx_j), its normal
turns by dn = (dr + v dtau)/sigma, and the collision rule v' = v - 2 (v.n) n, differentiated,
gives (equal masses; half of each change to i, the opposite half to j)

    dr' = dr - 2 (n.dr) n
    dv' = dv - 2 [(n.dv) n + (v.dn) n + (v.n) dn].

The tangent vector is renormalised every time unit and lambda is the mean growth rate of its
log-norm after a transient; one value per seed, and the mean over seeds with its standard error.
The gas: N equal disks (sigma = 1, mass 1) at number density rho in a periodic square, placed at
random without overlap, Maxwell velocities with zero momentum, scaled to kT = 1 exactly
(K = (N - 1) kT). A plain O(N^2) event loop in numpy: N of a few hundred runs in minutes.
"""
import argparse

import numpy as np

SIGMA = 1.0


def place(n, box, rng):
    """Random sequential placement without overlap (the area fraction must stay well below 0.5)."""
    x = np.empty((0, 2))
    while len(x) < n:
        trial = rng.uniform(0, box, 2)
        d = x - trial
        d -= box * np.round(d / box)
        if len(x) == 0 or np.min(np.einsum("ij,ij->i", d, d)) > SIGMA ** 2:
            x = np.vstack([x, trial])
    return x


def pair_times(x, v, i, box):
    """Time to the first contact of disk i with every disk, over the nine nearest images."""
    best = np.full(len(x), np.inf)
    for sx in (-1, 0, 1):
        for sy in (-1, 0, 1):
            d = x[i] - x + box * (np.round((x - x[i]) / box) + np.array([sx, sy]))
            u = v[i] - v
            b = np.einsum("ij,ij->i", d, u)
            c = np.einsum("ij,ij->i", d, d) - SIGMA ** 2
            uu = np.einsum("ij,ij->i", u, u)
            disc = b * b - uu * c
            ok = (b < 0) & (disc > 0)
            t = np.full(len(x), np.inf)
            t[ok] = c[ok] / (-b[ok] + np.sqrt(disc[ok]))   # the stable root (chapter 2.1)
            best = np.minimum(best, np.maximum(t, 0.0))
    best[i] = np.inf
    return best


def tangent_collision(i, j, x, v, dx, dv, box):
    """Collide i and j (in contact now) and carry the tangent vector through the collision."""
    r = x[i] - x[j]
    r -= box * np.round(r / box)
    n = r / np.linalg.norm(r)
    u = v[i] - v[j]
    un = u @ n
    dr, du = dx[i] - dx[j], dv[i] - dv[j]
    dtau = -(n @ dr) / un
    dn = (dr + u * dtau) / SIGMA
    dr_new = dr - 2 * (n @ dr) * n
    du_new = du - 2 * ((n @ du) * n + (u @ dn) * n + un * dn)
    for a, b, old, new in ((dx, None, dr, dr_new), (dv, None, du, du_new)):
        a[i] += (new - old) / 2
        a[j] -= (new - old) / 2
    v[i] -= un * n
    v[j] += un * n


def exponent(n, density, duration, transient, seed):
    """(lambda per time unit, collisions per disk per time unit) of one gas."""
    rng = np.random.default_rng(seed)
    box = np.sqrt(n / density)
    x = place(n, box, rng)
    v = rng.normal(size=(n, 2))
    v -= v.mean(axis=0)
    v *= np.sqrt((n - 1) / (0.5 * np.sum(v * v)))  # K = (N - 1) kT with kT = 1
    dx, dv = rng.normal(size=(n, 2)), rng.normal(size=(n, 2))
    norm = np.sqrt(np.sum(dx * dx) + np.sum(dv * dv))
    dx, dv = dx / norm, dv / norm
    table = np.array([pair_times(x, v, i, box) for i in range(n)])
    now, log_growth, collisions, next_renorm = 0.0, 0.0, 0, 1.0
    while now < duration:
        k = int(np.argmin(table))
        i, j = divmod(k, n)
        renormalise = next_renorm - now < table[i, j]   # the table holds times from now
        step = next_renorm - now if renormalise else table[i, j]
        x = (x + v * step) % box
        dx += dv * step
        table -= step
        now += step
        if renormalise:
            norm = np.sqrt(np.sum(dx * dx) + np.sum(dv * dv))
            if now > transient:
                log_growth += np.log(norm)
            dx, dv = dx / norm, dv / norm
            next_renorm += 1.0
            continue
        tangent_collision(i, j, x, v, dx, dv, box)
        if now > transient:
            collisions += 1
        for a in (i, j):
            table[a] = pair_times(x, v, a, box)
            table[:, a] = table[a]
    measured = duration - transient
    return log_growth / measured, 2 * collisions / (n * measured)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--disks", type=int, default=100)
    parser.add_argument("--density", type=float, default=0.4, help="number density rho (box_gas_1000: 0.4)")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--time", type=float, default=40.0, help="time units per seed")
    parser.add_argument("--transient", type=float, default=5.0, help="time units left out at the start")
    args = parser.parse_args()
    lams, rates = [], []
    for seed in range(1, args.seeds + 1):
        lam, nu = exponent(args.disks, args.density, args.time, args.transient, seed)
        lams.append(lam)
        rates.append(nu)
        print(f"seed {seed}: lambda {lam:.3f} per time unit, collision rate {nu:.3f} per disk")
    lams, rates = np.array(lams), np.array(rates)
    se = lams.std(ddof=1) / np.sqrt(len(lams)) if len(lams) > 1 else float("nan")
    per_collision = lams / rates
    print(f"N = {args.disks}, rho = {args.density}, kT = 1: lambda = {lams.mean():.2f} +- {se:.2f} per time unit, "
          f"{per_collision.mean():.2f} +- {per_collision.std(ddof=1) / np.sqrt(len(lams)):.2f} per mean free time "
          f"(collision rate {rates.mean():.3f})")


if __name__ == "__main__":
    main()
