// NeighbourShells: the neighbour lists of the `event` solver's shell design (Smallenburg,
// "Efficient event-driven simulations of hard spheres", Eur. Phys. J. E 45, 22 (2022)).
//
// Each disk i has a shell: a centre c_i (its position when its list was last built) and the
// list of the disks j with |c_i - c_j| < sigma_ij + 2 delta (minimum image in a periodic box),
// delta the shell width. While every disk stays within delta of its centre, two disks not in
// each other's lists are more than sigma_ij apart, so a disk can only touch the disks of its
// list. A disk reaching distance delta from its centre is an event (a "shell exit"): its list
// is rebuilt around its current position. This replaces the cell crossings of the cell-list
// design: a prediction reads a short array of neighbours instead of walking nine linked cells,
// and a disk has an exit only every delta of its path, not at every cell border.
//
// The lists are kept symmetric (j in i's list exactly when i is in j's), so a rebuild of i
// removes i from its old neighbours' lists and adds it to the new ones'. Each list is an array
// of fixed capacity in one flat block (no pointer chasing); when one fills up, every list is
// moved to a block twice as wide (grow), which the solver counts.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/numerics/prefetch.h"

namespace collide {

class NeighbourShells {
public:
    // n disks, each list with room for `capacity` neighbours at first.
    void reset(std::size_t n, std::uint32_t capacity) {
        capacity_ = std::max<std::uint32_t>(capacity, 4);
        shells_.assign(n, Shell{});
        list_.assign(n * capacity_, 0);
        grown_ = 0;
    }

    // The shell of disk i: its centre, its neighbour count and whether its neighbours may lie
    // across a periodic side (the minimum image is needed).
    struct Shell {
        double cx = 0, cy = 0;
        std::uint32_t count = 0;
        std::uint32_t minimum_image = 0;
    };
    Shell& shell(std::uint32_t i) { return shells_[i]; }
    const Shell& shell(std::uint32_t i) const { return shells_[i]; }

    const std::uint32_t* begin(std::uint32_t i) const { return &list_[std::size_t(i) * capacity_]; }
    const std::uint32_t* end(std::uint32_t i) const { return begin(i) + shells_[i].count; }

    // Adds j to i's list (not the reverse: the caller adds both ways).
    void add(std::uint32_t i, std::uint32_t j) {
        if (shells_[i].count == capacity_) grow();
        list_[std::size_t(i) * capacity_ + shells_[i].count++] = j;
    }
    // Removes j from i's list (the last entry takes its place: the order of a list carries no
    // meaning beyond the order of visits, which is that of the latest rebuilds).
    void remove(std::uint32_t i, std::uint32_t j) {
        std::uint32_t* l = &list_[std::size_t(i) * capacity_];
        std::uint32_t& count = shells_[i].count;
        for (std::uint32_t k = 0; k < count; ++k)
            if (l[k] == j) {
                l[k] = l[--count];
                return;
            }
    }
    void clear(std::uint32_t i) { shells_[i].count = 0; }

    // Requests disk i's shell and list (the first step of prefetching its prediction).
    void prefetch_list(std::uint32_t i) const {
        prefetch_line(&shells_[i]);
        prefetch_line(begin(i));
    }
    // Requests the records of disk i's neighbours (its list should have been requested first).
    template <typename Disks>
    void prefetch_neighbours(const Disks& disks, std::uint32_t i) const {
        const std::uint32_t* b = begin(i);
        for (const std::uint32_t* j = b; j != end(i); ++j) prefetch_line(&disks[*j]);
    }

    // After the disks were renumbered (order[new] = old, new_of[old] = new): moves every shell
    // and list to its disk's new number and renames the neighbours.
    void renumber(const std::vector<std::uint32_t>& order, const std::vector<std::uint32_t>& new_of) {
        const std::size_t n = shells_.size();
        shells_scratch_.resize(n);
        list_scratch_.resize(list_.size());
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t old = order[k];
            shells_scratch_[k] = shells_[old];
            const std::uint32_t* from = &list_[std::size_t(old) * capacity_];
            std::uint32_t* to = &list_scratch_[k * capacity_];
            for (std::uint32_t m = 0; m < shells_[old].count; ++m) to[m] = new_of[from[m]];
        }
        shells_.swap(shells_scratch_);
        list_.swap(list_scratch_);
    }

    std::uint32_t capacity() const { return capacity_; }
    // How often the lists were moved to wider blocks (a statistic).
    std::int64_t times_grown() const { return grown_; }

private:
    void grow() {
        const std::uint32_t wider = 2 * capacity_;
        std::vector<std::uint32_t> moved(shells_.size() * wider);
        for (std::size_t i = 0; i < shells_.size(); ++i)
            std::copy_n(&list_[i * capacity_], shells_[i].count, &moved[i * wider]);
        list_.swap(moved);
        capacity_ = wider;
        ++grown_;
    }

    std::uint32_t capacity_ = 4;
    std::vector<Shell> shells_;
    std::vector<std::uint32_t> list_;  // disk i's neighbours at [i * capacity_, i * capacity_ + count)
    std::vector<Shell> shells_scratch_;
    std::vector<std::uint32_t> list_scratch_;
    std::int64_t grown_ = 0;
};

}  // namespace collide
