# Galperin's digits of pi read as a formula: int(pi sqrt(M/m)). Right at M/m = 100^k, wrong
# in general: at mass ratio 2 there are 5 collisions, int(pi sqrt 2) = 4.
# hint: count_collisions(2) = 4
import math

def count_collisions(mass_ratio):
    return int(math.pi * math.sqrt(mass_ratio))
