// UniformGrid: the broad phase. The box is cut into square-ish cells at least as wide as the
// largest possible contact distance (2 r_max), so every disk that can touch disk i has its
// centre in i's cell or one of the 8 around it (the 3x3 neighbourhood).
//
// Built each step by a counting sort (no per-cell containers, so nothing is allocated per step):
//   1. count the disks in each cell,
//   2. exclusive prefix sum of the counts -> cell_start[c], the first slot of cell c,
//   3. scatter each disk index into its cell's next free slot of `sorted_index`.
// Disks of one cell are then contiguous in `sorted_index`, in increasing index order, so the
// neighbour order (and with it every floating-point sum over neighbours) is deterministic.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/scene/scene.h"

namespace collide {

// Cells per axis of a stepping grid: as many as fit with an edge of at least min_cell_size,
// halved on both axes while there are more than 2^26 (a huge box with few disks must not
// allocate a billion cells; larger cells stay correct, only slower).
struct GridDimensions {
    std::int64_t cells_x = 1, cells_y = 1;
};

// Cells of edge >= min_cell_size that fit along `length`, at least 1. The quotient is clamped
// before it becomes an integer: a box 1e20 radii wide gives more than 2^63 cells, whose
// conversion is undefined behaviour (C++ [conv.fpint]), and two axes of 2^32 cells overflow
// the product cells_x * cells_y. Callers compare products in double and halve from there.
inline std::int64_t cells_along(double length, double min_cell_size) {
    return std::int64_t(std::clamp(std::floor(length / min_cell_size), 1.0, 0x1p62));
}
inline GridDimensions grid_dimensions(const World& world, double min_cell_size) {
    GridDimensions d;
    d.cells_x = cells_along(world.width(), min_cell_size);
    d.cells_y = cells_along(world.height(), min_cell_size);
    const double max_cells = double(std::int64_t(1) << 26);
    while (double(d.cells_x) * double(d.cells_y) > max_cells) {
        d.cells_x = std::max<std::int64_t>(1, d.cells_x / 2);
        d.cells_y = std::max<std::int64_t>(1, d.cells_y / 2);
    }
    return d;
}

template <typename Real>
class UniformGrid {
public:
    // min_cell_size: the smallest allowed cell edge, normally 2 * r_max.
    void configure(const World& world, double min_cell_size) {
        if (!(min_cell_size > 0)) throw std::invalid_argument("grid cell size must be positive");
        world_ = world;
        periodic_ = world.boundary == Boundary::periodic;
        const GridDimensions d = grid_dimensions(world, min_cell_size);
        cells_x_ = d.cells_x;
        cells_y_ = d.cells_y;
        inv_cell_w_ = Real(double(cells_x_) / world.width());
        inv_cell_h_ = Real(double(cells_y_) / world.height());
        cell_start_.assign(cell_count() + 1, 0);
        // Neighbour cell offsets along each axis: {-1, 0, 1}, fewer when a periodic axis has
        // under 3 cells (otherwise a cell would be visited twice through the wrap).
        offsets_x_ = axis_offsets(cells_x_);
        offsets_y_ = axis_offsets(cells_y_);
    }

    void build(const Real* x, const Real* y, std::size_t n) {
        cell_of_.resize(n);
        sorted_index_.resize(n);
        std::fill(cell_start_.begin(), cell_start_.end(), 0u);
        for (std::size_t i = 0; i < n; ++i) {
            cell_of_[i] = std::uint32_t(cell_index(cell_x(x[i]), cell_y(y[i])));
            ++cell_start_[cell_of_[i] + 1];
        }
        for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
        next_.assign(cell_start_.begin(), cell_start_.end() - 1);
        for (std::size_t i = 0; i < n; ++i) sorted_index_[next_[cell_of_[i]]++] = std::uint32_t(i);
    }

    // Calls visit(j) for every disk j in the 3x3 cell neighbourhood of point (px, py),
    // including the disk at that point itself; the caller skips j == i.
    template <typename Visit>
    void for_each_candidate(Real px, Real py, Visit&& visit) const {
        const std::int64_t cx = cell_x(px), cy = cell_y(py);
        for (int oy : offsets_y_) {
            std::int64_t ny = cy + oy;
            if (!wrap_or_skip(ny, cells_y_)) continue;
            for (int ox : offsets_x_) {
                std::int64_t nx = cx + ox;
                if (!wrap_or_skip(nx, cells_x_)) continue;
                const std::int64_t c = cell_index(nx, ny);
                for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k)
                    visit(sorted_index_[k]);
            }
        }
    }

    // Calls visit(begin, end) for the slot ranges of `sorted_index` that hold the 3x3 cell
    // neighbourhood of cell (cx, cy): one range per row where the row's three cells are
    // contiguous (away from the side walls and wraps), one per cell elsewhere.
    template <typename Visit>
    void for_each_neighbour_range(std::int64_t cx, std::int64_t cy, Visit&& visit) const {
        for (int oy : offsets_y_) {
            std::int64_t ny = cy + oy;
            if (!wrap_or_skip(ny, cells_y_)) continue;
            if (cx >= 1 && cx + 1 < cells_x_) {
                visit(cell_start_[cell_index(cx - 1, ny)], cell_start_[cell_index(cx + 1, ny) + 1]);
                continue;
            }
            for (int ox : offsets_x_) {
                std::int64_t nx = cx + ox;
                if (!wrap_or_skip(nx, cells_x_)) continue;
                const std::int64_t c = cell_index(nx, ny);
                visit(cell_start_[c], cell_start_[c + 1]);
            }
        }
    }

    std::int64_t cells_x() const { return cells_x_; }
    std::int64_t cells_y() const { return cells_y_; }
    std::int64_t cell_count() const { return cells_x_ * cells_y_; }
    const std::vector<std::uint32_t>& cell_start() const { return cell_start_; }
    const std::vector<std::uint32_t>& sorted_index() const { return sorted_index_; }
    const std::vector<std::uint32_t>& cell_of() const { return cell_of_; }

    // Cell coordinates; points outside the box (a disk past a wall before clamping, or NaN)
    // are clamped to the border cells so that they are still found.
    std::int64_t cell_x(Real px) const { return clamp_cell((px - Real(world_.xmin)) * inv_cell_w_, cells_x_); }
    std::int64_t cell_y(Real py) const { return clamp_cell((py - Real(world_.ymin)) * inv_cell_h_, cells_y_); }
    std::int64_t cell_index(std::int64_t cx, std::int64_t cy) const { return cy * cells_x_ + cx; }

private:
    static std::int64_t clamp_cell(Real scaled, std::int64_t cells) {
        if (!(scaled >= Real(0))) return 0;  // also catches NaN
        if (scaled >= Real(cells)) return cells - 1;
        return std::int64_t(scaled);
    }
    bool wrap_or_skip(std::int64_t& c, std::int64_t cells) const {
        if (c >= 0 && c < cells) return true;
        if (!periodic_) return false;
        c = (c + cells) % cells;
        return true;
    }
    std::vector<int> axis_offsets(std::int64_t cells) const {
        if (!periodic_ || cells >= 3) return {-1, 0, 1};
        if (cells == 2) return {0, 1};
        return {0};
    }

    World world_;
    bool periodic_ = false;
    std::int64_t cells_x_ = 1, cells_y_ = 1;
    Real inv_cell_w_ = 1, inv_cell_h_ = 1;
    std::vector<int> offsets_x_, offsets_y_;
    std::vector<std::uint32_t> cell_start_, sorted_index_, cell_of_, next_;
};

}  // namespace collide
