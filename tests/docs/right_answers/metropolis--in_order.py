# Moves the disks in turn rather than at random, and draws the step uniformly in a disk of
# radius delta: each move still keeps the uniform measure (a symmetric proposal), so the
# sweep does too.
import math

def metropolis_sweep(x, radius, side, delta, rng):
    accepted = 0
    for i in range(len(x)):
        while True:                               # a point uniform in the disk |step| < delta
            dx, dy = rng.uniform(-delta, delta, 2)
            if dx * dx + dy * dy < delta * delta:
                break
        nx, ny = x[i, 0] + dx, x[i, 1] + dy
        if not (radius <= nx <= side - radius and radius <= ny <= side - radius):
            continue
        if any(math.hypot(nx - x[j, 0], ny - x[j, 1]) < 2 * radius for j in range(len(x)) if j != i):
            continue
        x[i] = nx, ny
        accepted += 1
    return accepted
