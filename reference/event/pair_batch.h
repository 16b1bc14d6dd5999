// Speed layer of the tuned `event` solver: the pair tests of one prediction, in batches.
//
// A prediction tests disk i against each disk of its 3x3 cells. Written as one loop, every
// neighbour costs two or three branches whose outcome is a coin toss (approaching or not, do
// the paths meet), and a mispredicted branch costs as much as the arithmetic of a whole test.
// PairBatch splits the loop in three: the walk of the cell lists gathers each neighbour's
// relative position, velocity and contact distance into short arrays; one pass without
// branches computes the quadratic of each and whether it collides at all; and only those that
// do pay the square root and the division. The arithmetic is that of
// event_time::pair_collision_time, by the same functions (physics/collision_time.h:
// pair_quadratic, pair_collides, pair_meeting_time), and the hits are taken in the order of
// the walk, so the earliest collision found, ties included, is the same one, bit for bit.
//
// What it buys: 16 to 23 % of the processor time per collision in the cache (N = 1e3) at
// area fractions 0.5 and 0.7, 11 to 21 % at N = 1e5, 3 to 6 % at 0.1, where most events are
// cell crossings (bench/journal.md, "event: branches the processor cannot predict"), although
// it runs about a fifth more instructions: the branches it removes were mispredicted about
// half the time.
#pragma once

#include <cmath>
#include <cstdint>

#include "physics/collision_time.h"

namespace collide {

class PairBatch {
public:
    static constexpr int capacity = 32;
    static_assert(capacity <= 256, "the hits are numbered in 8 bits");

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
            const event_time::PairQuadratic q = event_time::pair_quadratic(dx_[k], dy_[k], ux_[k], uy_[k], sigma_[k]);
            b_[k] = q.b, c_[k] = q.c, discriminant_[k] = q.discriminant;
            hit_[hits] = std::uint8_t(k);
            hits += event_time::pair_collides(q);
        }
        for (int h = 0; h < hits; ++h) {
            const int k = hit_[h];
            found(partner_[k], event_time::pair_meeting_time({b_[k], c_[k], discriminant_[k]}));
        }
        size_ = 0;
    }

private:
    int size_ = 0;
    alignas(16) double dx_[capacity], dy_[capacity], ux_[capacity], uy_[capacity], sigma_[capacity];
    alignas(16) double b_[capacity], c_[capacity], discriminant_[capacity];  // (the PairQuadratic of each)
    std::uint32_t partner_[capacity];
    std::uint8_t hit_[capacity];
};

}  // namespace collide
