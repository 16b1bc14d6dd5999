# Never proposes a move out of the box: the step window is clipped to the box. Near a wall the
# window is smaller, so the proposal from a disk near the wall and the one back to it differ in
# probability: not symmetric, and the walls' neighbourhood is undersampled.
# hint: is the proposal symmetric
import numpy as np

def metropolis_sweep(x, radius, side, delta, rng):
    n, accepted = len(x), 0
    for _ in range(n):
        i = rng.integers(n)
        low, high = np.maximum(x[i] - delta, radius), np.minimum(x[i] + delta, side - radius)
        new = rng.uniform(low, high)             # a window that depends on where the disk is
        r2 = ((x - new) ** 2).sum(axis=1)
        r2[i] = np.inf
        if r2.min() >= (2 * radius) ** 2:
            x[i] = new
            accepted += 1
    return accepted
