# Right offsets, and a stable order, but from a comparison sort: O(N log N), not a counting sort.
# hint: compar
def counting_sort(cell, n_cells):
    count = [0] * (n_cells + 1)
    for c in cell:
        count[c + 1] += 1
    for c in range(n_cells):
        count[c + 1] += count[c]
    order = sorted(range(len(cell)), key=lambda i: cell[i])
    return count, order
