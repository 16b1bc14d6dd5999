#include "event_statistics.h"

namespace collide {

SolverStats event_statistics(const Scene& scene, std::size_t disks, double now, const EventCounts& counts,
                             double kinetic_integral) {
    SolverStats s;
    s.contacts = counts.pair;
    s.steps = counts.pair + counts.wall + counts.cell + counts.shell;
    auto& c = s.counters;
    c["events_pair"] = double(counts.pair);
    c["events_wall"] = double(counts.wall);
    c["events_cell"] = double(counts.cell);
    c["events_stale"] = double(counts.stale);
    c["events_shell"] = double(counts.shell);
    c["simulated_time"] = now;
    const double t = now, n = double(disks), area = scene.world.width() * scene.world.height();
    if (t > 0 && n > 0) {
        // Every collision involves two disks: collisions per disk per unit time = 2 C / (N t).
        c["collision_rate"] = 2 * double(counts.pair) / (n * t);
        c["collisions_per_time"] = double(counts.pair) / t;
    }
    c["virial_sum"] = counts.virial;
    if (scene.periodic()) {
        if (!scene.has_gravity()) {
            c["kinetic_integral"] = kinetic_integral;
            if (t > 0) c["pressure"] = (kinetic_integral / t + counts.virial / (2 * t)) / area;
        }
        return s;
    }
    static const char* names[4] = {"wall_impulse_xmin", "wall_impulse_xmax", "wall_impulse_ymin", "wall_impulse_ymax"};
    double total = 0;
    for (int k = 0; k < 4 && counts.wall_impulse; ++k) {
        c[names[k]] = counts.wall_impulse[k].value();
        total += counts.wall_impulse[k].value();
    }
    c["wall_impulse"] = total;
    const double perimeter = 2 * (scene.world.width() + scene.world.height());
    if (t > 0) c["pressure"] = total / (perimeter * t);
    return s;
}

}  // namespace collide
