// Speed layer of the tuned `event` solver: the compact records. Everything an event reads of
// a disk lies on one 64-byte cache line, and everything it reads of the disk's calendar entry
// on another:
//   - `EventDisk`: the free flight (position and velocity at the disk's own clock), the clock,
//     the radius, the event counter and the disk's links in the cell list. Predicting reads
//     all of these for every neighbour, so a neighbour costs one cache line (the plain solver
//     keeps them in separate vectors);
//   - `EventSlot`: the disk's one prediction (kept apart from the calendar time, which the
//     calendar stores) and its inverse mass, carried in the disk's calendar slot
//     (event_queue.h), which each of its events reads and writes anyway.
//
// What it buys, together with the calendar (event_queue.h) and local clocks: 3.0x the
// collisions per second of `event-plain` with prefetching off (N = 1e5, area fraction 0.3,
// periodic, one core; `python3 bench/event_optimisations.py 100000`, median of three runs,
// before the batched pair tests of pair_batch.h, with which it is 3.8x;
// docs/course/5-making-it-fast.md). Each can only be switched off with the others, so the
// figure is theirs together.
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "event_cell_list.h"
#include "physics/collision_time.h"

namespace collide {

// (cell: a cell crossing, in the cell-list design; shell: a shell exit, in the neighbour-list
// design, neighbour_shells.h.)
enum class EventKind : std::uint8_t { none, pair, wall, cell, shell };

// A disk's prediction. Walls and cell borders are numbered: 0 = x low, 1 = x high, 2 = y low,
// 3 = y high. The earliest pair collision is kept apart from the earliest wall or border
// event: a cell crossing does not change the disk's course, so the pair collision found
// before stays valid and only the newly entered cells need a look
// (EventSolver::predict_after_crossing).
struct EventPrediction {
    double pair_time = event_time::never;  // the earliest pair collision: its (absolute) time,
    std::uint32_t partner = 0;             // the other disk,
    std::uint32_t partner_count = 0;       // and that disk's event counter when predicted
    EventKind kind = EventKind::none;      // the earlier of the pair collision and the event below
    std::uint8_t border = 0;               // the wall/border number (kind wall or cell)
};

// What the calendar slot of a disk carries: its prediction and its inverse mass, both read at
// each of its events, on the slot's cache line. A stone has inverse mass 0
// (core/particle_state.h).
struct EventSlot {
    EventPrediction prediction;
    double inv_mass = 0;
};

// One disk: its free flight (position and velocity valid at the disk's own clock t), its event
// counter and its place in the cell list, in one 64-byte record.
struct alignas(64) EventDisk {
    double x, y, vx, vy;
    double t;             // the disk's clock
    double radius;
    std::uint32_t count;  // event counter: bumped whenever the disk changes course
    CellLinks links;      // cell and neighbours in the cell (event_cell_list.h)
};
static_assert(sizeof(EventDisk) == 64);

// A disk's position and velocity as the vectors of the equations (views, no copies: x, y and
// vx, vy are adjacent). Eigen::Vector2d arithmetic rounds each component exactly as the scalar
// lines it replaces (one operation per component, in the same order, no FMA), so the
// trajectories are the same, bit for bit.
static_assert(offsetof(EventDisk, y) == offsetof(EventDisk, x) + sizeof(double) &&
              offsetof(EventDisk, vy) == offsetof(EventDisk, vx) + sizeof(double));
inline Eigen::Map<Eigen::Vector2d> position_of(EventDisk& d) { return Eigen::Map<Eigen::Vector2d>(&d.x); }
inline Eigen::Map<const Eigen::Vector2d> position_of(const EventDisk& d) {
    return Eigen::Map<const Eigen::Vector2d>(&d.x);
}
inline Eigen::Map<Eigen::Vector2d> velocity_of(EventDisk& d) { return Eigen::Map<Eigen::Vector2d>(&d.vx); }
inline Eigen::Map<const Eigen::Vector2d> velocity_of(const EventDisk& d) {
    return Eigen::Map<const Eigen::Vector2d>(&d.vx);
}

}  // namespace collide
