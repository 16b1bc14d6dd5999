# Tests the walls but not the other disks: moves that overlap another disk are accepted.
# hint: two disks overlap
import numpy as np

def metropolis_sweep(x, radius, side, delta, rng):
    n, accepted = len(x), 0
    for _ in range(n):
        i = rng.integers(n)
        new = x[i] + rng.uniform(-delta, delta, 2)
        if np.all(new >= radius) and np.all(new <= side - radius):   # no test against the other disks
            x[i] = new
            accepted += 1
    return accepted
