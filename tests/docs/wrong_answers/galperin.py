# Counts only the disk-disk collisions: half of Galperin's number.
def count_collisions(mass_ratio):
    m, M = 1.0, float(mass_ratio)
    v, V = 0.0, -1.0
    count = 0
    while True:
        if V < v:
            v, V = ((m - M) * v + 2 * M * V) / (m + M), ((M - m) * V + 2 * m * v) / (m + M)
            count += 1
        elif v < 0:
            v = -v
        else:
            return count
