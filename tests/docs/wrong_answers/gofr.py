# Exercise 2.8 without the nearest image: the pairs that meet across the box's edge are missed,
# so g is too low in every bin (by the share of pairs near the edges).
# hint: nearest image
import numpy as np


def pair_correlation(x, box, sigma, width, bins):
    n, box = len(x), np.asarray(box, dtype=float)
    i, j = np.triu_indices(n, 1)
    d = x[i] - x[j]
    r = np.hypot(d[:, 0], d[:, 1])
    edges = sigma + width * np.arange(bins + 1) / bins
    counts, _ = np.histogram(r, bins=edges)
    ideal = n * (n - 1) / 2 * np.pi * (edges[1:] ** 2 - edges[:-1] ** 2) / box.prod()
    return counts / ideal
