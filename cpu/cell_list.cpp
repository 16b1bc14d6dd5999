#include "cell_list.h"

#include <algorithm>
#include <stdexcept>

#include "parallel_for.h"

namespace collide::cpu {

void CellList::configure(const World& world, double min_cell_size) {
    if (!(min_cell_size > 0)) throw std::invalid_argument("cpu: grid cell size must be positive (largest radius > 0)");
    cells_x_ = std::max<std::int64_t>(1, std::int64_t(world.width() / min_cell_size));
    cells_y_ = std::max<std::int64_t>(1, std::int64_t(world.height() / min_cell_size));
    // Same cap as core/uniform_grid.h: a huge box with few disks must not allocate 1e9 cells.
    const std::int64_t max_cells = std::int64_t(1) << 26;
    while (cells_x_ * cells_y_ > max_cells) {
        cells_x_ = std::max<std::int64_t>(1, cells_x_ / 2);
        cells_y_ = std::max<std::int64_t>(1, cells_y_ / 2);
    }
    xmin_ = float(world.xmin);
    ymin_ = float(world.ymin);
    inv_cell_w_ = float(double(cells_x_) / world.width());
    inv_cell_h_ = float(double(cells_y_) / world.height());
    cell_start_.assign(std::size_t(cell_count()) + 1, 0);
}

void CellList::build(const float* x, const float* y, std::size_t n, int threads) {
    cell_of_.resize(n);
    sorted_index_.resize(n);
    // 1. The cell of every disk (parallel: the only floating-point work of the build).
    parallel_for(n, threads, [&](std::size_t begin, std::size_t end) -> std::int64_t {
        for (std::size_t i = begin; i < end; ++i)
            cell_of_[i] = std::uint32_t(cell_y(y[i]) * cells_x_ + cell_x(x[i]));
        return 0;
    });
    // 2. Count per cell, shifted by one so that the prefix sum below gives start offsets.
    std::fill(cell_start_.begin(), cell_start_.end(), 0u);
    for (std::size_t i = 0; i < n; ++i) ++cell_start_[cell_of_[i] + 1];
    // 3. Exclusive prefix sum: cell_start_[c] = number of disks in cells before c.
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    // 4. Stable scatter: cell_start_[c] is advanced while filling cell c and afterwards
    //    equals the start of cell c + 1; shifting back by one cell restores the starts.
    for (std::size_t i = 0; i < n; ++i) sorted_index_[cell_start_[cell_of_[i]]++] = std::uint32_t(i);
    for (std::size_t c = cell_start_.size() - 1; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
    cell_start_[0] = 0;
}

void CellList::mark_sorted(int threads) {
    parallel_for(sorted_index_.size(), threads, [&](std::size_t begin, std::size_t end) -> std::int64_t {
        for (std::size_t k = begin; k < end; ++k) sorted_index_[k] = std::uint32_t(k);
        return 0;
    });
}

}  // namespace collide::cpu
