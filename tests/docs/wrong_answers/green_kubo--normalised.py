# Integrates the normalised C(t) = <v(0).v(t)> / <v.v>: a time (the memory's), not D.
# hint: that is the integral of the normalised C(t), a time
import numpy as np


def green_kubo(v, dt, t_max):
    lags = int(round(t_max / dt)) + 1
    z = np.array([(v[k:] * v[:len(v) - k]).sum(axis=2).mean() for k in range(lags)])
    c = z / z[0]
    return 0.5 * dt * (c.sum() - (c[0] + c[-1]) / 2)
