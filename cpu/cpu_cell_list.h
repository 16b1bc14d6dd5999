// CellList: the broad phase of the `cpu` backend, a uniform grid rebuilt by counting sort
// (the same scheme as core/uniform_grid.h: one flat index buffer) with three changes
// for speed:
//   * the whole sort runs in parallel (below), in one parallel region;
//   * the caller decides what "placing disk i into slot k" means: writing an index buffer
//     (sorted_index) or moving the disk's data itself into cell order (CpuSolver's reorder);
//   * a neighbourhood is visited as contiguous ranges of slots, one per row of the 3x3 block
//     (cells (cx-1, cy) .. (cx+1, cy) are adjacent in cell order), so the contact loop walks
//     three ranges instead of nine cells.
//
// Parallel counting sort. The disks are cut into one static block per thread, in index
// order. Each thread
//   1. computes the cell of each disk of its block and counts its disks per cell, into its
//      own histogram covering only the cells its block touches ([lo, hi]: when the disks
//      are already in cell order, as after CpuSolver's reorder, these ranges barely overlap
//      and the histograms together are about one cell array long);
//   2. turns, for one slice of the cells, the counts into slot offsets, visiting (cell, block)
//      in the fixed order cell-major, block-minor;
//   3. places the disks of its block at those offsets, in index order.
// Within a cell, block 0's disks come first, then block 1's, ..., each in increasing index
// order: every cell lists its disks in increasing index order, whatever the number of
// threads (a stable sort). The neighbour order, and with it every floating-point sum over
// neighbours, is therefore the same for any thread count.
#pragma once

#include <omp.h>

#include <cstdint>
#include <vector>

#include "core/scene/scene.h"
#include "parallel_for.h"

namespace collide::cpu {

// Slots [begin, end) of the cell order.
struct SlotRange {
    std::uint32_t begin, end;
};

class CellList {
public:
    // Cells at least min_cell_size (= 2 r_max, the largest contact distance) wide, so that
    // every contact partner of a disk lies in its 3x3 cell neighbourhood.
    void configure(const World& world, double min_cell_size);

    // Sorts disks 0 .. n-1 by the cell of (x[i], y[i]) on `threads` threads and calls
    // place(i, k) once for each disk: disk i goes to slot k of the cell order. Calls for
    // different disks run concurrently; each k is given out once.
    template <typename Place>
    void build(const float* x, const float* y, std::size_t n, int threads, Place&& place);

    // build() that records the cell order in sorted_index(): slot k holds disk sorted_index()[k].
    void build_index(const float* x, const float* y, std::size_t n, int threads) {
        sorted_index_.resize(n);
        std::uint32_t* index = sorted_index_.data();
        build(x, y, n, threads, [index](std::uint32_t i, std::uint32_t k) { index[k] = i; });
    }
    const std::uint32_t* sorted_index() const { return sorted_index_.data(); }

    std::int64_t cells_x() const { return cells_x_; }
    std::int64_t cells_y() const { return cells_y_; }
    std::int64_t cell_count() const { return cells_x_ * cells_y_; }
    // Slots of cell c = cy * cells_x() + cx: [cell_start()[c], cell_start()[c + 1]).
    const std::uint32_t* cell_start() const { return cell_start_.data(); }

    // The column of cells a disk at x = px belongs to: the rule build() sorts by.
    std::int64_t column_of(float px) const { return cell_index(px, xmin_, inv_cell_w_, std::int32_t(cells_x_)); }

    // The cell starts of row `row` (cell_start() + row * cells_x(), cells_x() + 1 entries):
    // for a row outside the box, a row of zeros (reflecting walls: no cells) or the row it
    // wraps to (periodic walls; the caller keeps to rows -1 .. cells_y()).
    template <bool Periodic>
    const std::uint32_t* row_start(std::int64_t row) const {
        if (row >= 0 && row < cells_y_) return cell_start_.data() + row * cells_x_;
        if constexpr (Periodic) return cell_start_.data() + (row < 0 ? row + cells_y_ : row - cells_y_) * cells_x_;
        return no_cells_.data();
    }

    // The slot ranges that hold the candidates of every disk in cell (cx, cy): its
    // own cell and the 8 around it, row by row from bottom to top (at most 6 ranges: a row
    // splits in two where periodic walls wrap it). Returns how many were written to `out`.
    template <bool Periodic>
    int neighbour_ranges(std::int64_t cx, std::int64_t cy, SlotRange out[6]) const;

private:
    // A static block of disks [begin, end) and its histogram over cells lo .. lo + count.size() - 1.
    struct Block {
        std::size_t begin = 0, end = 0;
        std::uint32_t lo = 0;
        std::vector<std::uint32_t> count;  // counts, then (after step 2) next free slot per cell
    };

    std::uint32_t cell_of(float px, float py) const {
        return std::uint32_t(cell_index(py, ymin_, inv_cell_h_, std::int32_t(cells_y_)) * std::int32_t(cells_x_) +
                             cell_index(px, xmin_, inv_cell_w_, std::int32_t(cells_x_)));
    }
    // Points outside the box (a disk past a wall before clamping, or NaN) go to a border
    // cell. Written with selects on 32-bit values rather than branches so that the loop
    // over disks vectorises (at most 2^26 cells, so every value fits).
    static std::int32_t cell_index(float p, float lo, float inv_width, std::int32_t cells) {
        float scaled = (p - lo) * inv_width;
        scaled = scaled >= 0.0f ? scaled : 0.0f;  // also NaN -> 0
        scaled = scaled < float(cells) ? scaled : float(cells);
        const std::int32_t c = std::int32_t(scaled);
        return c < cells - 1 ? c : cells - 1;
    }
    void count_block(Block& b, const float* x, const float* y);  // step 1
    std::uint32_t slice_total(std::size_t c0, std::size_t c1) const;
    void slice_offsets(std::size_t c0, std::size_t c1, std::uint32_t first_slot);  // step 2
    template <bool Periodic>
    void add_row(std::int64_t row, std::int64_t cx, SlotRange out[6], int& count) const;

    float xmin_ = 0, ymin_ = 0, inv_cell_w_ = 1, inv_cell_h_ = 1;
    std::int64_t cells_x_ = 1, cells_y_ = 1;
    std::vector<std::uint32_t> cell_of_;       // cell of each disk
    std::vector<std::uint32_t> cell_start_;    // first slot of each cell; cell_count() + 1 entries
    std::vector<std::uint32_t> sorted_index_;  // disk in each slot (build_index only)
    std::vector<std::uint32_t> no_cells_;      // cells_x_ + 1 zeros: the starts of a row outside the box
    std::vector<Block> blocks_;                // one per thread of the last build
    std::vector<std::uint32_t> slice_totals_;  // disks per slice of cells (step 2)
};

template <typename Place>
void CellList::build(const float* x, const float* y, std::size_t n, int threads, Place&& place) {
    cell_of_.resize(n);
    // The three steps below, run by every thread of a team (or by the caller alone, outside any
    // OpenMP region, for few disks: a region of one thread still costs a team set-up per call).
    // The omp directives inside are orphaned: they bind to the team running them, if any.
    auto build_steps = [&] {
        // The team may be smaller than asked for; the blocks follow the team actually running.
        const std::size_t team = std::size_t(omp_get_num_threads()), t = std::size_t(omp_get_thread_num());
#pragma omp single
        {
            blocks_.resize(team);
            slice_totals_.assign(team, 0);
            for (std::size_t b = 0; b < team; ++b) {
                blocks_[b].begin = n * b / team;
                blocks_[b].end = n * (b + 1) / team;
            }
        }  // implicit barrier
        Block& mine = blocks_[t];
        count_block(mine, x, y);
#pragma omp barrier
        // Step 2 over slice t of the cells; a slice's first slot is the number of disks in
        // the slices before it.
        const std::size_t cells = std::size_t(cell_count());
        const std::size_t c0 = cells * t / team, c1 = cells * (t + 1) / team;
        slice_totals_[t] = slice_total(c0, c1);
#pragma omp barrier
        std::uint32_t first_slot = 0;
        for (std::size_t s = 0; s < t; ++s) first_slot += slice_totals_[s];
        slice_offsets(c0, c1, first_slot);
#pragma omp barrier
        // Step 3: place the block's disks, in index order.
        std::uint32_t* next = mine.count.data() - mine.lo;  // next[c] for c in [lo, hi]
        for (std::size_t i = mine.begin; i < mine.end; ++i) place(std::uint32_t(i), next[cell_of_[i]]++);
    };
    if (!runs_inline(threads, n)) {
#pragma omp parallel num_threads(threads)
        build_steps();
    } else {
        build_steps();
    }
    cell_start_[std::size_t(cell_count())] = std::uint32_t(n);
}

template <bool Periodic>
void CellList::add_row(std::int64_t row, std::int64_t cx, SlotRange out[6], int& count) const {
    const std::uint32_t* start = cell_start_.data() + row * cells_x_;
    auto add = [&](std::int64_t first_cell, std::int64_t last_cell) {
        const SlotRange r{start[first_cell], start[last_cell + 1]};
        if (r.begin != r.end) out[count++] = r;
    };
    if (!Periodic || cells_x_ < 3) {
        // Reflecting walls: clip the block at the border. Periodic with fewer than 3 columns:
        // the whole row, once (the wrapped neighbours are the row's own cells).
        add(Periodic ? 0 : (cx > 0 ? cx - 1 : 0), Periodic ? cells_x_ - 1 : (cx + 1 < cells_x_ ? cx + 1 : cells_x_ - 1));
    } else if (cx == 0) {  // left neighbour is the last column
        add(cells_x_ - 1, cells_x_ - 1);
        add(0, 1);
    } else if (cx == cells_x_ - 1) {  // right neighbour is the first column
        add(cx - 1, cx);
        add(0, 0);
    } else {
        add(cx - 1, cx + 1);
    }
}

template <bool Periodic>
int CellList::neighbour_ranges(std::int64_t cx, std::int64_t cy, SlotRange out[6]) const {
    int count = 0;
    if constexpr (!Periodic) {
        // Reflecting walls: the 3x3 block clipped at the border, one range per row (rows
        // outside the box read from a row of zeros: empty ranges, no branch).
        const std::int64_t lo = cx > 0 ? cx - 1 : 0, hi = cx + 2 < cells_x_ ? cx + 2 : cells_x_;
        for (std::int64_t row = cy - 1; row <= cy + 1; ++row) {
            const std::uint32_t* start = row >= 0 && row < cells_y_ ? cell_start_.data() + row * cells_x_ : no_cells_.data();
            out[count++] = SlotRange{start[lo], start[hi]};
        }
        return count;
    }
    if (cells_y_ < 3) {  // every row, once
        for (std::int64_t row = 0; row < cells_y_; ++row) add_row<Periodic>(row, cx, out, count);
        return count;
    }
    for (std::int64_t dy = -1; dy <= 1; ++dy) add_row<Periodic>((cy + dy + cells_y_) % cells_y_, cx, out, count);
    return count;
}

}  // namespace collide::cpu
