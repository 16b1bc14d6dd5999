# Draws again until the move is legal: the chain then favours disks with room around them.
# hint: keep the old configuration
import numpy as np

def metropolis_sweep(x, radius, side, delta, rng):
    n = len(x)
    for _ in range(n):
        i = rng.integers(n)
        while True:                               # draws again until the move is legal
            new = x[i] + rng.uniform(-delta, delta, 2)
            if np.any(new < radius) or np.any(new > side - radius):
                continue
            r2 = ((x - new) ** 2).sum(axis=1)
            r2[i] = np.inf
            if r2.min() >= (2 * radius) ** 2:
                break
        x[i] = new
    return n
