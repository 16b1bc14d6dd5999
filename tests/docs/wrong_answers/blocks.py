# The standard error of independent samples: too small for a correlated series.
import numpy as np

def block_standard_error(x, block):
    x = np.asarray(x)
    return x.std(ddof=1) / np.sqrt(len(x))
