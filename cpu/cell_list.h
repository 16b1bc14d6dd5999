// CellList: the broad phase of the `cpu` backend, a uniform grid rebuilt by counting sort
// (the same scheme as core/uniform_grid.h, seed 001's flat index buffer) with two changes
// for speed:
//   * the cell of every disk, the only floating-point part, is computed in parallel;
//   * a neighbourhood is visited as contiguous ranges of the sorted index buffer, one per
//     row of the 3x3 block (cells (cx-1, cy) .. (cx+1, cy) are adjacent in the buffer), so
//     the contact loop walks three ranges instead of nine cells.
// Within a cell, disks stay in increasing index order (the scatter is a stable sort), so the
// neighbour order, and with it every floating-point sum over neighbours, is fixed.
#pragma once

#include <cstdint>
#include <vector>

#include "core/scene.h"

namespace collide::cpu {

class CellList {
public:
    // Cells at least min_cell_size (= 2 r_max, the largest contact distance) wide, so that
    // every contact partner of a disk lies in its 3x3 cell neighbourhood.
    void configure(const World& world, double min_cell_size);

    // Rebuilds the lists from positions. Parallel part on `threads` threads.
    void build(const float* x, const float* y, std::size_t n, int threads);

    // After the particles were permuted into sorted order (CpuSolver::sort_by_cell), the
    // sorted index buffer is the identity.
    void mark_sorted(int threads);

    // Calls visit(begin, end) for each contiguous range [begin, end) of sorted_index() that
    // holds the candidates of a disk at (px, py): its own cell and the 8 around it, row by row.
    template <bool Periodic, typename Visit>
    void for_each_neighbour_range(float px, float py, Visit&& visit) const;

    const std::uint32_t* sorted_index() const { return sorted_index_.data(); }
    std::int64_t cell_count() const { return cells_x_ * cells_y_; }

private:
    std::int64_t cell_x(float px) const { return clamp_cell((px - xmin_) * inv_cell_w_, cells_x_); }
    std::int64_t cell_y(float py) const { return clamp_cell((py - ymin_) * inv_cell_h_, cells_y_); }
    // Points outside the box (a disk past a wall before clamping, or NaN) go to a border cell.
    static std::int64_t clamp_cell(float scaled, std::int64_t cells) {
        if (!(scaled >= 0.0f)) return 0;
        if (scaled >= float(cells)) return cells - 1;
        return std::int64_t(scaled);
    }
    template <bool Periodic, typename Visit>
    void visit_row(std::int64_t row, std::int64_t cx, Visit& visit) const;

    float xmin_ = 0, ymin_ = 0, inv_cell_w_ = 1, inv_cell_h_ = 1;
    std::int64_t cells_x_ = 1, cells_y_ = 1;
    std::vector<std::uint32_t> cell_of_;       // cell of each disk
    std::vector<std::uint32_t> cell_start_;    // first slot of each cell; cell_count() + 1 entries
    std::vector<std::uint32_t> sorted_index_;  // disk indices grouped by cell
};

template <bool Periodic, typename Visit>
void CellList::visit_row(std::int64_t row, std::int64_t cx, Visit& visit) const {
    const std::uint32_t* start = cell_start_.data() + row * cells_x_;
    if (!Periodic || cells_x_ < 3) {
        // Reflecting walls: clip the block at the border. Periodic with fewer than 3 columns:
        // the whole row, once (the wrapped neighbours are the row's own cells).
        const std::int64_t lo = Periodic ? 0 : (cx > 0 ? cx - 1 : 0);
        const std::int64_t hi = Periodic ? cells_x_ - 1 : (cx + 1 < cells_x_ ? cx + 1 : cells_x_ - 1);
        visit(start[lo], start[hi + 1]);
    } else if (cx == 0) {  // left neighbour is the last column
        visit(start[cells_x_ - 1], start[cells_x_]);
        visit(start[0], start[2]);
    } else if (cx == cells_x_ - 1) {  // right neighbour is the first column
        visit(start[cx - 1], start[cx + 1]);
        visit(start[0], start[1]);
    } else {
        visit(start[cx - 1], start[cx + 2]);
    }
}

template <bool Periodic, typename Visit>
void CellList::for_each_neighbour_range(float px, float py, Visit&& visit) const {
    const std::int64_t cx = cell_x(px), cy = cell_y(py);
    if (Periodic && cells_y_ < 3) {  // every row, once
        for (std::int64_t row = 0; row < cells_y_; ++row) visit_row<Periodic>(row, cx, visit);
        return;
    }
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
        std::int64_t row = cy + dy;
        if (row < 0 || row >= cells_y_) {
            if (!Periodic) continue;
            row = (row + cells_y_) % cells_y_;
        }
        visit_row<Periodic>(row, cx, visit);
    }
}

}  // namespace collide::cpu
