// The largest difference between two states of the same disks, for tests that hold two solvers
// against each other. In a periodic box a disk on a side may sit at lo in one solver and just
// below lo + L in the other (wrapped back): the nearest images are compared.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide::test {

struct StateDifference {
    double position = 0, velocity = 0;  // largest over disks and components
};

// `relative`: |a - b| / max(1, |a|) (relative for large values, absolute for small ones);
// otherwise |a - b|.
inline StateDifference state_difference(const Scene& scene, const ParticleState<double>& a,
                                        const ParticleState<double>& b, bool relative) {
    auto diff = [relative](double x, double dx) { return std::fabs(dx) / (relative ? std::max(1.0, std::fabs(x)) : 1.0); };
    StateDifference d;
    const World& w = scene.world;
    for (std::size_t i = 0; i < a.size(); ++i) {
        double dx = a.x[i] - b.x[i], dy = a.y[i] - b.y[i];
        if (scene.periodic()) {
            dx -= w.width() * std::round(dx / w.width());
            dy -= w.height() * std::round(dy / w.height());
        }
        d.position = std::max({d.position, diff(a.x[i], dx), diff(a.y[i], dy)});
        d.velocity = std::max({d.velocity, diff(a.vx[i], a.vx[i] - b.vx[i]), diff(a.vy[i], a.vy[i] - b.vy[i])});
    }
    return d;
}

}  // namespace collide::test
