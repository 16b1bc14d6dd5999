// Speed layer of the tuned `event` solver: renumbering the disks in cell order (memory
// locality). A prediction reads the record of every disk in the 3x3 cells around a disk. If
// the disks are numbered in cell order, those records lie in three runs of consecutive records
// (one per row of cells), a few cache lines each; in the scene's order, or after the disks have
// diffused, each is a separate cache miss once the records outgrow the cache (N = 1e5: 6.4 MB).
// So the solver renumbers its disks cell by cell at load and then every `interval()` events.
//
// The renumbering is exact: it moves the records and the calendar slots with their predictions
// as they are (no re-prediction, no position is touched, the calendar keeps its buckets),
// keeps each cell's list in its order (so neighbours are visited in the same order and equal
// collision times resolve the same way), and the calendar breaks ties by the original index.
// The events are therefore the same, bit for bit, as without renumbering
// (tests/reference/test_cell_order_renumbering.cpp, test_event_brute_force.cpp).
//
// What it buys: in runs of a few events per disk, nothing: -6 % at N = 1e5 and -9 % at 1e6
// (area fraction 0.3, periodic, one core; `python3 bench/event_optimisations.py 100000`, median
// of three runs, and one run at 1000000; docs/course/5-making-it-fast.md), the cost of the
// renumberings themselves. It is meant for
// long runs, in which the disks drift far from the memory order they started in; that bench
// does not measure that case.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "event_cell_list.h"
#include "event_memory.h"
#include "event_queue.h"
#include "event_records.h"

namespace collide {

// The disks are renumbered after about this many events per disk (see default_interval).
inline constexpr std::int64_t renumber_events_per_disk = 4;

class CellOrderRenumbering {
public:
    // The default interval for n disks: renumber_events_per_disk events per disk, plus 1000.
    static std::int64_t default_interval(std::size_t n) { return renumber_events_per_disk * std::int64_t(n) + 1000; }

    void set_interval(std::int64_t events) { interval_ = events; }
    std::int64_t interval() const { return interval_; }
    // Counts one event; true when the disks are due for renumbering.
    bool count_event() { return ++events_since_ >= interval_; }

    // Renumbers the disks in cell order: disk k becomes the disk that was order()[k]. Moves the
    // records (relinking the cells), the calendar slots, every array in `per_disk` and
    // `original`, and renames the partners of the predictions.
    void apply(EventArray<EventDisk>& disks, CellList& cells, EventQueue<EventSlot>& queue,
               const std::vector<std::vector<double>*>& per_disk, std::vector<std::uint32_t>& original);

    // The last renumbering: order()[new] = old, and new_of()[old] = new.
    const std::vector<std::uint32_t>& order() const { return order_; }
    const std::vector<std::uint32_t>& new_of() const { return new_of_; }

private:
    std::int64_t interval_ = 0;
    std::int64_t events_since_ = 0;
    std::vector<std::uint32_t> order_;   // order_[new] = old
    std::vector<std::uint32_t> new_of_;  // and new_of_[old] = new (both kept: no allocation per renumbering)
    // Scratch space, kept so that no renumbering allocates (and clears) memory.
    EventArray<EventDisk> disks_scratch_;
    std::vector<double> real_scratch_;
    std::vector<std::uint32_t> index_scratch_;
};

}  // namespace collide
