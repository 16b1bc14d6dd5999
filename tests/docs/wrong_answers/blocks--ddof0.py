# Block means right, but their spread with ddof = 0: too small by sqrt((n - 1)/n).
# hint: ddof
import numpy as np

def block_standard_error(x, block):
    n = len(x) // block
    means = np.asarray(x[:n * block]).reshape(n, block).mean(axis=1)
    return means.std() / np.sqrt(n)
