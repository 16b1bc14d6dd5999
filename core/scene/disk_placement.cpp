#include "core/scene/disk_placement.h"

#include <algorithm>
#include <cmath>

#include "core/numerics/disk_overlap.h"

namespace collide {

DiskPlacement::DiskPlacement(const World& world, double max_radius, std::size_t expected_disks)
    : world_(world), periodic_(world.boundary == Boundary::periodic) {
    // Cell side >= 2 r_max, enlarged if needed to keep about 4 cells per disk at most.
    const double max_cells = 4.0 * double(expected_disks) + 1024.0;
    const double side = std::max(2.0 * max_radius, std::sqrt(world.width() * world.height() / max_cells));
    // Capped per axis too, for very elongated boxes (10^9 x 10^-9).
    cells_x_ = std::int64_t(std::clamp(world.width() / side, 1.0, max_cells));
    cells_y_ = std::int64_t(std::clamp(world.height() / side, 1.0, std::max(1.0, max_cells / double(cells_x_))));
    // Stretch the cells to tile the box exactly (each side still >= 2 r_max), so that the
    // periodic wrap of cell indices matches the wrap of positions.
    cell_w_ = world.width() / double(cells_x_);
    cell_h_ = world.height() / double(cells_y_);
    head_.assign(std::size_t(cells_x_ * cells_y_), -1);
    next_.reserve(expected_disks);
    x_.reserve(expected_disks);
    y_.reserve(expected_disks);
    r_.reserve(expected_disks);
}

// Minimum-image convention: the separation along a periodic axis brought into [-L/2, L/2].
static double minimum_image(double d, double length) { return d - length * std::rint(d / length); }

std::int64_t DiskPlacement::cell_of(double pos, double lo, double side, std::int64_t cells) const {
    const auto c = std::int64_t(std::floor((pos - lo) / side));
    return std::clamp<std::int64_t>(c, 0, cells - 1);
}

std::int64_t DiskPlacement::find_overlap(double x, double y, double r) const {
    const std::int64_t cx = cell_of(x, world_.xmin, cell_w_, cells_x_), cy = cell_of(y, world_.ymin, cell_h_, cells_y_);
    // With fewer than 3 cells on a periodic axis, offsets -1 and +1 reach the same cell:
    // visit each cell of that axis once instead.
    const std::int64_t span_x = std::min<std::int64_t>(3, cells_x_), span_y = std::min<std::int64_t>(3, cells_y_);
    for (std::int64_t oy = 0; oy < (periodic_ ? span_y : 3); ++oy) {
        std::int64_t ny = periodic_ && cells_y_ < 3 ? oy : cy + oy - 1;
        if (periodic_) ny = (ny + cells_y_) % cells_y_;
        else if (ny < 0 || ny >= cells_y_) continue;
        for (std::int64_t ox = 0; ox < (periodic_ ? span_x : 3); ++ox) {
            std::int64_t nx = periodic_ && cells_x_ < 3 ? ox : cx + ox - 1;
            if (periodic_) nx = (nx + cells_x_) % cells_x_;
            else if (nx < 0 || nx >= cells_x_) continue;
            for (std::int64_t j = head_[std::size_t(ny * cells_x_ + nx)]; j >= 0; j = next_[std::size_t(j)]) {
                double dx = x - x_[std::size_t(j)], dy = y - y_[std::size_t(j)];
                if (periodic_) {
                    dx = minimum_image(dx, world_.width());
                    dy = minimum_image(dy, world_.height());
                }
                const double contact = (r + r_[std::size_t(j)]) * (1.0 - 1e-12);
                if (centres_closer_than(dx, dy, contact)) return j;
            }
        }
    }
    return -1;
}

void DiskPlacement::insert(double x, double y, double r) {
    const std::int64_t cell = cell_of(y, world_.ymin, cell_h_, cells_y_) * cells_x_ + cell_of(x, world_.xmin, cell_w_, cells_x_);
    next_.push_back(head_[std::size_t(cell)]);
    head_[std::size_t(cell)] = std::int64_t(x_.size());
    x_.push_back(x);
    y_.push_back(y);
    r_.push_back(r);
}

}  // namespace collide
