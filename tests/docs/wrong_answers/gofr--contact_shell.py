# Exercise 2.8 with every shell taken at the contact distance, 2 pi sigma dr: right in the first
# bins, and too high by r / sigma further out.
# hint: 2 pi r dr
import numpy as np


def pair_correlation(x, box, sigma, width, bins):
    n, box = len(x), np.asarray(box, dtype=float)
    i, j = np.triu_indices(n, 1)
    d = x[i] - x[j]
    d -= box * np.round(d / box)
    r = np.hypot(d[:, 0], d[:, 1])
    edges = sigma + width * np.arange(bins + 1) / bins
    counts, _ = np.histogram(r, bins=edges)
    ideal = n * (n - 1) / 2 * 2 * np.pi * sigma * (width / bins) / box.prod()
    return counts / ideal
