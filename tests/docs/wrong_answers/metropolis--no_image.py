# Tests overlaps without the nearest periodic image: disks overlap across the boundary.
# hint: nearest image
import numpy as np

def metropolis_sweep(x, sigma, box, delta, rng):
    n, accepted = len(x), 0
    for _ in range(n):
        i = rng.integers(n)
        new = (x[i] + rng.uniform(-delta, delta, 2)) % box
        r2 = ((x - new) ** 2).sum(axis=1)         # no nearest image
        r2[i] = np.inf
        if r2.min() >= sigma ** 2:
            x[i] = new
            accepted += 1
    return accepted
