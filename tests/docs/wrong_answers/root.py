# The textbook root: right in exact arithmetic, loses the gap's digits to cancellation.
import math

def collision_time(dx, dy, ux, uy, sigma):
    b = dx * ux + dy * uy
    c = dx * dx + dy * dy - sigma * sigma
    uu = ux * ux + uy * uy
    disc = b * b - uu * c
    if b >= 0 or disc <= 0:
        return None
    return (-b - math.sqrt(disc)) / uu
