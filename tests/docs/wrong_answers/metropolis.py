# Draws again until the move is legal: the chain then favours disks with room around them.
# hint: keeps the old configuration
import numpy as np

def metropolis_sweep(x, sigma, box, delta, rng):
    n = len(x)
    for _ in range(n):
        i = rng.integers(n)
        while True:                               # draws again until the move is legal
            new = (x[i] + rng.uniform(-delta, delta, 2)) % box
            d = x - new
            d -= box * np.round(d / box)
            r2 = (d ** 2).sum(axis=1)
            r2[i] = np.inf
            if r2.min() >= sigma ** 2:
                break
        x[i] = new
    return n
