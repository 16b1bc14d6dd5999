#include "cpu_cell_list.h"

#include <algorithm>
#include <stdexcept>

#include "core/uniform_grid.h"

namespace collide::cpu {

void CellList::configure(const World& world, double min_cell_size) {
    if (!(min_cell_size > 0)) throw std::invalid_argument("cpu: grid cell size must be positive (largest radius > 0)");
    const GridDimensions d = grid_dimensions(world, min_cell_size);  // the same cells as UniformGrid
    cells_x_ = d.cells_x;
    cells_y_ = d.cells_y;
    xmin_ = float(world.xmin);
    ymin_ = float(world.ymin);
    inv_cell_w_ = float(double(cells_x_) / world.width());
    inv_cell_h_ = float(double(cells_y_) / world.height());
    cell_start_.assign(std::size_t(cell_count()) + 1, 0);
    no_cells_.assign(std::size_t(cells_x_) + 1, 0);
}

void CellList::count_block(Block& b, const float* x, const float* y) {
    if (b.begin == b.end) {
        b.lo = 0;
        b.count.clear();
        return;
    }
    // The cells (a loop the compiler vectorises) and the range of cells they fall in.
    std::uint32_t* cell = cell_of_.data();
    for (std::size_t i = b.begin; i < b.end; ++i) cell[i] = cell_of(x[i], y[i]);
    std::uint32_t lo = cell[b.begin], hi = lo;
    for (std::size_t i = b.begin; i < b.end; ++i) {
        lo = std::min(lo, cell[i]);
        hi = std::max(hi, cell[i]);
    }
    b.lo = lo;
    // Room for every cell, once: assign() allocates exactly what it is asked for, so a range
    // one cell wider than last step's would reallocate, and a fresh allocation of megabytes
    // comes from the kernel as new pages (hundreds of page faults, each page zeroed).
    if (b.count.capacity() < std::size_t(cell_count())) b.count.reserve(std::size_t(cell_count()));
    b.count.assign(hi - lo + 1, 0);
    std::uint32_t* count = b.count.data() - lo;
    for (std::size_t i = b.begin; i < b.end; ++i) ++count[cell[i]];
}

std::uint32_t CellList::slice_total(std::size_t c0, std::size_t c1) const {
    std::uint32_t total = 0;
    for (const Block& b : blocks_) {
        const std::size_t lo = std::max<std::size_t>(c0, b.lo), hi = std::min(c1, b.lo + b.count.size());
        for (std::size_t c = lo; c < hi; ++c) total += b.count[c - b.lo];
    }
    return total;
}

// cell_start[c] = first_slot + disks in cells c0 .. c-1; each block's count for cell c
// becomes the slot its first disk in c goes to (blocks in order: the sort is stable).
// The slice is cut where a block's cell range begins or ends, so that within each piece the
// blocks covering it are fixed and the inner loop is a plain prefix sum over them.
void CellList::slice_offsets(std::size_t c0, std::size_t c1, std::uint32_t first_slot) {
    std::vector<std::size_t> cuts{c0, c1};
    for (const Block& b : blocks_) {
        for (std::size_t edge : {std::size_t(b.lo), b.lo + b.count.size()})
            if (edge > c0 && edge < c1) cuts.push_back(edge);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

    std::uint32_t* start = cell_start_.data();
    std::uint32_t slot = first_slot;
    std::vector<std::uint32_t*> covering;  // next[c] of each block covering the piece, in block order
    for (std::size_t piece = 0; piece + 1 < cuts.size(); ++piece) {
        const std::size_t u = cuts[piece], v = cuts[piece + 1];
        covering.clear();
        for (Block& b : blocks_)
            if (b.lo <= u && u < b.lo + b.count.size()) covering.push_back(b.count.data() - b.lo);
        if (covering.empty()) {  // no disk in these cells
            std::fill(start + u, start + v, slot);
        } else if (covering.size() == 1) {  // one block: a plain exclusive prefix sum
            std::uint32_t* next = covering.front();
            for (std::size_t c = u; c < v; ++c) {
                start[c] = slot;
                const std::uint32_t n = next[c];
                next[c] = slot;
                slot += n;
            }
        } else {
            for (std::size_t c = u; c < v; ++c) {
                start[c] = slot;
                for (std::uint32_t* next : covering) {
                    const std::uint32_t n = next[c];
                    next[c] = slot;
                    slot += n;
                }
            }
        }
    }
}

}  // namespace collide::cpu
