// DiskPlacement: the disks placed so far while building an initial state, in a cell list,
// so that "does a new disk at (x, y) with radius r overlap any placed disk?" costs O(1)
// instead of O(N). This is what makes random sequential addition (RSA) of 10^6 disks take
// seconds rather than hours.
//
// Cells are squares of side >= 2 r_max, so a disk can only overlap disks whose centres lie
// in its own cell or the 8 around it. Each cell keeps a singly linked list of the disks in
// it (head_ per cell, next_ per disk): two flat integer arrays, no allocation per cell.
#pragma once

#include <cstdint>
#include <vector>

#include "core/scene/scene.h"

namespace collide {

class DiskPlacement {
public:
    // `max_radius`: the largest radius that will be inserted or queried. `expected_disks`
    // bounds the number of cells (a huge box with tiny disks gets bigger cells, not
    // billions of empty ones).
    DiskPlacement(const World& world, double max_radius, std::size_t expected_disks);

    // Index (in insertion order) of a placed disk that overlaps a disk of radius r at
    // (x, y), or -1 if there is none. Touching disks do not overlap: the test is
    // |x_i - x_j| < (r_i + r_j)(1 - 1e-12), the small tolerance absorbing the rounding of
    // lattice positions at exactly touching spacings, tested without squaring (disk_overlap.h),
    // so that it holds for radii of any size. Periodic worlds use minimum images.
    std::int64_t find_overlap(double x, double y, double r) const;

    void insert(double x, double y, double r);
    std::size_t size() const { return x_.size(); }

private:
    std::int64_t cell_of(double pos, double lo, double side, std::int64_t cells) const;

    World world_;
    bool periodic_;
    double cell_w_, cell_h_;           // cell sides, both >= 2 r_max
    std::int64_t cells_x_, cells_y_;
    std::vector<std::int64_t> head_;  // first disk in each cell, -1 when empty
    std::vector<std::int64_t> next_;  // next disk in the same cell, -1 at the end
    std::vector<double> x_, y_, r_;
};

}  // namespace collide
