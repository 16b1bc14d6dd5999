// Speed layer of the tuned `event` solver: the pair tests of one prediction, in batches.
//
// A prediction tests disk i against each disk of its 3x3 cells. Written as one loop, every
// neighbour costs two or three branches whose outcome is a coin toss (approaching or not, do
// the paths meet), and a mispredicted branch costs as much as the arithmetic of a whole test.
// PairBatch splits the loop in three: the walk of the cell lists gathers each neighbour's
// relative position, velocity and contact distance into short arrays; one pass without
// branches decides which of them can collide at all (the tests of
// event_time::pair_collision_time, physics/collision_time.h, as 0/1 flags); and only those
// pay the square root and the division. Every quantity is computed with the same operations
// in the same order as pair_collision_time, and the hits are taken in the order of the walk,
// so the earliest collision found, ties included, is the same one, bit for bit.
#pragma once

#include <cmath>
#include <cstdint>

#include "physics/collision_time.h"

namespace collide {

class PairBatch {
public:
    static constexpr int capacity = 32;

    bool full() const { return size_ == capacity; }
    void add(std::uint32_t j, double dx, double dy, double ux, double uy, double sigma) {
        partner_[size_] = j;
        dx_[size_] = dx, dy_[size_] = dy, ux_[size_] = ux, uy_[size_] = uy, sigma_[size_] = sigma;
        ++size_;
    }
    // Calls found(j, dt) for every gathered neighbour j that collides with the disk, dt its
    // collision time from now (as pair_collision_time gives it), in the order gathered; then
    // empties the batch.
    template <typename Found>
    void flush(Found&& found) {
        int hits = 0;
        for (int k = 0; k < size_; ++k) {
            const double b = dx_[k] * ux_[k] + dy_[k] * uy_[k];
            const double c = dx_[k] * dx_[k] + dy_[k] * dy_[k] - sigma_[k] * sigma_[k];
            const double uu = ux_[k] * ux_[k] + uy_[k] * uy_[k];
            const double discriminant = b * b - uu * c;
            // Approaching, and either touching already (time 0) or on paths that meet: the
            // tests of pair_collision_time, written so that a NaN takes the same way there and
            // here (it reaches the quotient, a NaN time, which no comparison takes as earliest).
            const bool hit = (b < 0) & ((c <= 0) | !(discriminant <= 0));
            b_[k] = b, c_[k] = c, discriminant_[k] = discriminant;
            hit_[hits] = std::uint8_t(k);
            hits += hit;
        }
        for (int h = 0; h < hits; ++h) {
            const int k = hit_[h];
            found(partner_[k], c_[k] <= 0 ? 0.0 : c_[k] / (-b_[k] + std::sqrt(discriminant_[k])));
        }
        size_ = 0;
    }

private:
    int size_ = 0;
    alignas(16) double dx_[capacity], dy_[capacity], ux_[capacity], uy_[capacity], sigma_[capacity];
    alignas(16) double b_[capacity], c_[capacity], discriminant_[capacity];
    std::uint32_t partner_[capacity];
    std::uint8_t hit_[capacity];
};

}  // namespace collide
