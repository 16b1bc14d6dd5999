# Fits an exponential decay T0 exp(-t/tau): the wrong law (that is cooling at a fixed rate).
import numpy as np

def haff_tau(t, T):
    slope, _ = np.polyfit(t, np.log(T), 1)
    return -1 / slope
