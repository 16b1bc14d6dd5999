# Galperin's count in closed form, in exact rational arithmetic: the number of collisions is
# the number of k >= 1 with k theta < pi, theta = atan(sqrt(m/M)), simulated here exactly.
from fractions import Fraction

def count_collisions(mass_ratio):
    m, M = Fraction(1), Fraction(mass_ratio)
    v, V, count = Fraction(0), Fraction(-1), 0
    while True:
        if V < v:
            v, V = ((m - M) * v + 2 * M * V) / (m + M), ((M - m) * V + 2 * m * v) / (m + M)
        elif v < 0:
            v = -v
        else:
            return count
        count += 1
