# Exercise 2.8 normalised by N^2 / 2 pairs: each disk has N - 1 partners, not N, so g is low by
# (N - 1) / N in every bin (1.7 % at N = 60: small, and exactly the kind of 1/N error chapter 4.6
# measures in the pressure).
# hint: N (N - 1) / 2 pairs
import numpy as np


def pair_correlation(x, box, sigma, width, bins):
    n, box = len(x), np.asarray(box, dtype=float)
    i, j = np.triu_indices(n, 1)
    d = x[i] - x[j]
    d -= box * np.round(d / box)
    r = np.hypot(d[:, 0], d[:, 1])
    edges = sigma + width * np.arange(bins + 1) / bins
    counts, _ = np.histogram(r, bins=edges)
    ideal = n * n / 2 * np.pi * (edges[1:] ** 2 - edges[:-1] ** 2) / box.prod()
    return counts / ideal
