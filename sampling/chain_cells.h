// The cell list of the samplers (ecmc, metropolis): the box cut into cells wider than a given
// distance (ecmc: the contact distance sigma), each holding the disks whose centre lies in it.
// In ecmc a disk that moves along +x (or +y) by at most the distance to its cell's far edge
// can only meet disks of its own column and the next one, in its row and the two beside it:
// 6 cells, not 9 (disks of the column behind lie behind it); along -x (in a box with walls)
// its own column and the previous one. Membership is explicit (a disk knows its cell; a cell
// lists its disks in a fixed-size slot array): a disk changes cell only when the chain moves it
// across an edge, never by re-binning a rounded coordinate, so no disk can fall between two
// cells; a disk on the edge between two cells belongs to the one it came into.
// (metropolis re-bins an accepted disk from its new position: a jump, not a slide.)
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide {

class ChainCells {
public:
    // Cells of edge > sigma over a box of `length[0]` x `length[1]` from `origin`. Throws if the
    // box is narrower than 3 cells on an axis (the 3 rows beside a disk must be distinct).
    void configure(const double origin[2], const double length[2], double sigma) {
        for (int a = 0; a < 2; ++a) {
            origin_[a] = origin[a];
            length_[a] = length[a];
            // Strictly wider than sigma, so that rounding at an edge cannot hide a contact.
            count_[a] = int(std::floor(length[a] / (sigma * (1 + 1e-9))));
            if (count_[a] < 3)
                throw std::runtime_error("the box is " + std::to_string(length[a] / sigma) +
                                         " disk diameters wide; a sampler needs at least 3 cells of one diameter (and a little more) across");
            side_[a] = length[a] / count_[a];
        }
        // At most one centre per square of diagonal < sigma: (ceil(side sqrt2 / sigma) + 1)^2.
        const double per_axis = std::ceil(std::max(side_[0], side_[1]) * std::sqrt(2.0) / sigma) + 1;
        capacity_ = int(per_axis * per_axis);
        members_.assign(std::size_t(count_[0]) * count_[1] * capacity_, 0);
        occupancy_.assign(std::size_t(count_[0]) * count_[1], 0);
    }

    int count(int axis) const { return count_[axis]; }
    double side(int axis) const { return side_[axis]; }
    double origin(int axis) const { return origin_[axis]; }
    double length(int axis) const { return length_[axis]; }
    // The cell index of column/row coordinates c[0], c[1] (each already in range).
    int index(int cx, int cy) const { return cx + count_[0] * cy; }
    // The cell coordinate of a position along `axis` (for placing the start configuration).
    int coordinate_of(int axis, double position) const {
        const int c = int(std::floor((position - origin_[axis]) / side_[axis]));
        return c < 0 ? 0 : c >= count_[axis] ? count_[axis] - 1 : c;
    }

    int occupancy(int cell) const { return occupancy_[cell]; }
    const std::uint32_t* members(int cell) const { return &members_[std::size_t(cell) * capacity_]; }

    // Adds disk `i` to `cell`; returns its slot there.
    int insert(int cell, std::uint32_t i) {
        if (occupancy_[cell] == capacity_) throw std::runtime_error("a sampler's cell is full (overlapping disks?)");
        const int slot = occupancy_[cell]++;
        members_[std::size_t(cell) * capacity_ + slot] = i;
        return slot;
    }
    // Removes the disk in `slot` of `cell` by moving the cell's last disk into its place;
    // returns that disk (whose slot is now `slot`), or the removed one if it was the last.
    std::uint32_t erase(int cell, int slot) {
        std::uint32_t* m = &members_[std::size_t(cell) * capacity_];
        const int last = --occupancy_[cell];
        m[slot] = m[last];
        return m[slot];
    }

private:
    double origin_[2] = {0, 0}, length_[2] = {1, 1}, side_[2] = {1, 1};
    int count_[2] = {1, 1};
    int capacity_ = 1;
    std::vector<std::uint32_t> members_;
    std::vector<int> occupancy_;
};

}  // namespace collide
