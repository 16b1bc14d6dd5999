// The statistics every event-driven solver reports, under one set of names (`event` and
// `event-plain` alike, so suites, physics rows and tests read them the same way): event
// counts, the collision rate, the collision virial and the pressure made from it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/numerics/compensated_sum.h"
#include "core/scene/scene.h"
#include "core/solver.h"

namespace collide {

// What an event-driven solver has counted so far.
struct EventCounts {
    std::int64_t pair = 0, wall = 0, cell = 0, stale = 0;  // events processed (stale: dropped)
    double virial = 0;                   // sum over collisions of d.(J n) (the collision virial)
    const CompensatedSum* wall_impulse = nullptr;  // momentum given to each wall: xmin, xmax, ymin, ymax
    std::int64_t shell = 0;  // shell exits (the neighbour-list design of `event`)
};

// steps, contacts and the counters events_*, simulated_time, collision_rate (collisions per disk
// per unit time, 2 C / (N t)), collisions_per_time, virial_sum, and the pressure:
//  - periodic, no gravity: the virial theorem for impulsive forces in 2-D (Alder & Wainwright,
//    J. Chem. Phys. 33 (1960) 1439; Allen & Tildesley §2.4), P A = <K> + (1 / (2 t)) V, with
//    <K> = kinetic_integral / t (docs/event-driven.md);
//  - walls: momentum given to the walls per unit time and unit wall length.
SolverStats event_statistics(const Scene& scene, std::size_t disks, double now, const EventCounts& counts,
                             double kinetic_integral);

}  // namespace collide
