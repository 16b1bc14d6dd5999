# Offsets without the end of the last cell (n_cells entries instead of n_cells + 1).
def counting_sort(cell, n_cells):
    count = [0] * n_cells
    for c in cell:
        count[c] += 1
    start, total = [], 0
    for c in range(n_cells):
        start.append(total)
        total += count[c]
    order = sorted(range(len(cell)), key=lambda i: cell[i])
    return start, order
