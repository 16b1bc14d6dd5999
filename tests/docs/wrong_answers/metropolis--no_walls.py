# Keeps the centres in the box but forgets the disks' size at the walls: a centre may come
# within one radius of a wall, so the disk pokes through it.
# hint: closer than its radius
import numpy as np

def metropolis_sweep(x, radius, side, delta, rng):
    n, accepted = len(x), 0
    for _ in range(n):
        i = rng.integers(n)
        new = x[i] + rng.uniform(-delta, delta, 2)
        if np.any(new < 0) or np.any(new > side):    # the centre's box, not the disk's
            continue
        r2 = ((x - new) ** 2).sum(axis=1)
        r2[i] = np.inf
        if r2.min() >= (2 * radius) ** 2:
            x[i] = new
            accepted += 1
    return accepted
