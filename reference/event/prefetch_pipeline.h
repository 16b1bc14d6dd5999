// Speed layer of the tuned `event` solver: the prefetch pipeline. Software pipelining over the
// coming events. Successive events fall at unrelated places in the box, so once the state
// outgrows the cache every event waits for a chain of cache misses: its calendar slot and
// record, then the list heads of the cells it will look at (which need the record's cell),
// then the records in those cells (which need the heads), then the next records in the same
// cells. The calendar knows the disks of the next few events (EventQueue::next_upcoming), so
// each is taken through this chain one link per event, ahead of time (prefetch_line,
// core/numerics/prefetch.h: a request the compiler cannot delete):
//   stage 0: its calendar slot and record are requested;
//   stage 1 (one event later): the list heads of its cells (cells_to_visit), and its
//            predicted partner's record and slot, whatever the event (a collision reads and
//            writes both; a crossing reads the kept partner's record, whose event counter it
//            checks; for a wall the requests are spare);
//   stage 2: the first record of each of those cells, and the list heads around the partner;
//   stage 3: the second record of each of those cells, only where the cells hold a disk or
//            more on average (second_records: very dilute gases, very dense or crowded cells);
//            where they hold fewer, few lists have a second record and the stage cost more
//            than it saved.
// The misses of three or four coming events then overlap with the work of the current one,
// instead of following each other. Prefetches are hints: the events, and their order, are the
// same with or without them (tests/reference/test_event_brute_force.cpp forces it on small
// gases; docs/event-driven.md, "Performance").
//
// What it buys: 1.6x the collisions per second of the same solver without it at N = 1e6,
// where the state lives in main memory, and 1.06x at N = 1e5 on a processor whose 32 MB L3
// cache holds that state (1.46x on an earlier machine with less cache) (area fraction 0.3,
// periodic, one core; `python3 bench/event_optimisations.py 1000000` and `100000`;
// docs/course/5-making-it-fast.md). Below 2^16 disks it costs time (see
// prefetch_from_disks), so it is off there unless [backend.event] prefetch = "on".
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/numerics/prefetch.h"
#include "event_cell_list.h"
#include "event_memory.h"
#include "event_queue.h"
#include "event_records.h"
#include "neighbour_shells.h"

namespace collide {

// The pipeline runs from this many disks on: 2^16 disks have 8 MiB of records and calendar
// slots, four times what a core's L2 cache holds. Below, most of the state stays in the cache
// and the prefetching mostly costs time: per collision +22 % at N = 1e3, +35 % at 1e4, +10 %
// at 3e4, +2 % at 4.5e4, then -11 % at 6.6e4 and -23 % at 1e5 (area fraction 0.5, medians of
// 4 concurrent runs, docs/event-driven.md).
inline constexpr std::size_t prefetch_from_disks = std::size_t(1) << 16;

class PrefetchPipeline {
public:
    using Queue = EventQueue<EventSlot>;
    static constexpr std::uint32_t none = Queue::none;

    // Whether the pipeline runs, and whether it runs stage 3; forgets every disk it holds.
    void configure(bool on, bool second_records) {
        on_ = on;
        second_records_ = second_records;
        named_events_ = 0;
        forget();
    }
    bool on() const { return on_; }
    // "on", "on, second records" or "off" (the run's provenance).
    std::string describe() const { return on_ ? (second_records_ ? "on, second records" : "on") : "off"; }

    // Takes each disk in the pipeline one stage further and names the next (before an event).
    void advance(const EventArray<EventDisk>& disks, const CellList& cells, Queue& queue) {
        const Upcoming& third = upcoming_[2];
        if (third.disk != none && second_records_) cells.prefetch_records(disks, third.cells, 1);
        const Upcoming& second = upcoming_[1];
        if (second.disk != none) {
            cells.prefetch_records(disks, second.cells, 0);
            const EventPrediction& p = queue.payload(second.disk).prediction;
            if (p.kind == EventKind::pair) cells.prefetch_heads(cells.neighbourhood_block(disks[p.partner].links));
        }
        Upcoming& first = upcoming_[0];
        if (first.disk != none) {
            first.cells = cells_to_visit(disks, cells, queue, first.disk);  // (its record arrived: its cell is known)
            cells.prefetch_heads(first.cells);
            // A collision reads and writes its partner's record and slot; a crossing reads the
            // event counter in its kept partner's record (predict_after_crossing). Both are
            // requested whatever the event: a test of its kind (a collision or a crossing, a
            // coin toss in a dilute gas) costs more than a request that is not needed. (The
            // partner is always a disk: predictions name disk 0 until they find one, and
            // renumbering renames them.)
            const EventPrediction& p = queue.payload(first.disk).prediction;
            // (A prefetch of a wrong address would go unnoticed, even by AddressSanitizer.)
            assert(p.partner < disks.size());
            prefetch_line(&disks[p.partner]);
            prefetch_line(queue.slot_address(p.partner));
            if (p.kind == EventKind::pair) partners_.remember(p.partner);
        }
        name_next(disks, queue, [](std::uint32_t) {});
    }

    // The same for the neighbour-list design (neighbour_shells.h), whose predictions read a
    // disk's list and the records it names instead of cells: the list's address follows from
    // the disk's number, so the chain is one link shorter.
    //   stage 0: its calendar slot, record and list are requested;
    //   stage 1: the records its list names, and its predicted partner's record, slot and list;
    //   stage 2: the records the partner's list names.
    // A shell exit reads the cells around its new centre, which lies in the cell of its old
    // one or next to it: stage 1 requests the list heads of the 3x3 cells around the old
    // centre, and stage 2 their first records.
    void advance(const EventArray<EventDisk>& disks, const CellList& cells, const NeighbourShells& shells,
                 Queue& queue) {
        const Upcoming& second = upcoming_[1];
        if (second.disk != none) {
            const EventPrediction& p = queue.payload(second.disk).prediction;
            if (p.kind == EventKind::pair) shells.prefetch_neighbours(disks, p.partner);
            if (p.kind == EventKind::shell) cells.prefetch_records(disks, second.cells, 0);
        }
        Upcoming& first = upcoming_[0];
        if (first.disk != none) {
            shells.prefetch_neighbours(disks, first.disk);
            const EventPrediction& p = queue.payload(first.disk).prediction;
            if (p.kind == EventKind::shell) {
                first.cells = cells.neighbourhood_block(disks[first.disk].links);
                cells.prefetch_heads(first.cells);
            }
            if (p.kind == EventKind::pair) {
                prefetch_line(&disks[p.partner]);
                prefetch_line(queue.slot_address(p.partner));
                shells.prefetch_list(p.partner);
                partners_.remember(p.partner);
            }
        }
        name_next(disks, queue, [&](std::uint32_t disk) { shells.prefetch_list(disk); });
    }

    // The statistic events_named_ahead: events (of all four kinds, stale ones included) whose
    // disk, or for a collision either disk, was among the last 32 disks the look-ahead named.
    // Such an event found its memory requested ahead, at least partly (a disk named one event
    // before has only its record in the cache); the others wait for each of their cache misses
    // in turn.
    void count_if_named(std::uint32_t i, const EventPrediction& p) {
        if (on_ && names_.holds(i, p.kind == EventKind::pair ? p.partner : i)) ++named_events_;
    }
    std::int64_t events_named_ahead() const { return named_events_; }

    // Forgets every disk the pipeline holds (on load and after renumbering, which renames them).
    void forget() {
        for (Upcoming& u : upcoming_) u = Upcoming{};
        partners_.forget();
        names_.forget();
    }

private:
    // Stage 0 of both designs: the stages move on by one event, and the next event not yet
    // named enters: its record and calendar slot are requested, and whatever else its design
    // reads first (`also_request`: nothing for the cells, its list for the shells).
    template <typename AlsoRequest>
    void name_next(const EventArray<EventDisk>& disks, Queue& queue, AlsoRequest&& also_request) {
        upcoming_[2] = upcoming_[1];
        upcoming_[1] = upcoming_[0];
        upcoming_[0] = Upcoming{next_to_name(queue), {}};
        if (upcoming_[0].disk == none) return;
        prefetch_line(&disks[upcoming_[0].disk]);
        prefetch_line(queue.slot_address(upcoming_[0].disk));
        also_request(upcoming_[0].disk);
        names_.remember(upcoming_[0].disk);
    }

    // The cells whose lists the coming event of disk k will read: for a cell crossing the cell
    // it enters and the three beyond (crossing_block), else the 3x3 block around its cell.
    static CellList::Block cells_to_visit(const EventArray<EventDisk>& disks, const CellList& cells,
                                          const Queue& queue, std::uint32_t k) {
        const EventPrediction& p = queue.payload(k).prediction;
        if (p.kind == EventKind::cell) return cells.crossing_block(disks[k].links, p.border);
        return cells.neighbourhood_block(disks[k].links);
    }

    // The next disk for the pipeline: the look-ahead's next one that is not the partner of a
    // collision already in it. About half the collisions were predicted by both disks, so each
    // has a calendar entry for it; the entry served second vanishes (serving the first
    // re-predicts both disks), and the pipeline already requested both disks' records and
    // slots for the first. Naming the second would waste a stage and, worse, let the front gain
    // on the look-ahead: the front serves more entries than there are events, the walk names
    // one per event, and where the front reaches the bucket the walk is in, the walk leaves
    // that bucket's remaining entries unnamed (docs/event-driven.md, "Prefetching the coming
    // events", has the shares of events named with and without). A partner whose own entry is
    // another, later event is passed over only if the walk reaches it while it is among the
    // last few partners, which is rare (its entry lies far ahead).
    std::uint32_t next_to_name(Queue& queue) {
        std::uint32_t next = queue.next_upcoming();
        for (unsigned passed = 0; next != none && passed < partners_.size && partners_.holds(next); ++passed)
            next = queue.next_upcoming();
        return next;
    }

    // The last K disks put into it, oldest overwritten first.
    template <unsigned K>
    struct RecentDisks {
        static constexpr unsigned size = K;
        std::uint32_t disk[K];
        unsigned next = 0;  // the slot written next (always below K)
        void remember(std::uint32_t k) {
            disk[next] = k;
            next = next + 1 == K ? 0 : next + 1;
        }
        // Whether it holds a or b. Every slot is compared, without an early exit, so that the
        // compiler makes it a few vector compares (it runs at every event).
        bool holds(std::uint32_t a, std::uint32_t b) const {
            std::uint32_t found = 0;
            for (std::uint32_t d : disk) found |= std::uint32_t(d == a) | std::uint32_t(d == b);
            return found != 0;
        }
        bool holds(std::uint32_t a) const { return holds(a, a); }
        void forget() { std::fill(disk, disk + K, none); }
    };

    struct Upcoming {
        std::uint32_t disk = none;
        CellList::Block cells;  // cells_to_visit(disk), from stage 1 on
    };

    bool on_ = false;
    bool second_records_ = false;  // stage 3 (where cells hold a disk or more on average)
    // The disks of coming events at stages 1, 2 and 3 of their prefetch chain (none if none).
    Upcoming upcoming_[3];
    // The partners of the last few collisions taken into the pipeline, which the look-ahead
    // passes over (see next_to_name).
    RecentDisks<4> partners_;
    // The disks the look-ahead named last, to count the events it named ahead (count_if_named).
    RecentDisks<32> names_;
    std::int64_t named_events_ = 0;
};

}  // namespace collide
