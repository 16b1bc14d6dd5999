# The exact first contact of the given doubles, solved in 50 digits: no rounding of c at all.
import mpmath

def collision_time(dx, dy, ux, uy, sigma):
    mpmath.mp.dps = 50
    dx, dy, ux, uy, sigma = (mpmath.mpf(v) for v in (dx, dy, ux, uy, sigma))
    b = dx * ux + dy * uy
    c = dx * dx + dy * dy - sigma * sigma
    uu = ux * ux + uy * uy
    disc = b * b - uu * c
    if b >= 0 or disc <= 0:
        return None
    return float(c / (-b + mpmath.sqrt(disc)))
