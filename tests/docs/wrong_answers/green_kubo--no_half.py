# The integral of <v(0).v(t)> without two dimensions' factor 1/2: twice D.
# hint: the factor 1/2 of two dimensions is missing
import numpy as np


def green_kubo(v, dt, t_max):
    lags = int(round(t_max / dt)) + 1
    z = np.array([(v[k:] * v[:len(v) - k]).sum(axis=2).mean() for k in range(lags)])
    return dt * (z.sum() - (z[0] + z[-1]) / 2)
