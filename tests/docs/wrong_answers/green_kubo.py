# Green-Kubo with three dimensions' factor 1/3 (D = (1/3) int <v(0).v(t)> dt): a disk moves in two.
# hint: 1/3 is three dimensions' factor
import numpy as np


def green_kubo(v, dt, t_max):
    lags = int(round(t_max / dt)) + 1
    z = np.array([(v[k:] * v[:len(v) - k]).sum(axis=2).mean() for k in range(lags)])
    return dt * (z.sum() - (z[0] + z[-1]) / 2) / 3
