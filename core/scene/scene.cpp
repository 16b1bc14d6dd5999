#include "core/scene/scene.h"

#include <algorithm>
#include <cmath>

namespace collide {

const char* to_string(Boundary b) { return b == Boundary::reflect ? "reflect" : "periodic"; }

const char* to_string(StepOrder o) {
    return o == StepOrder::collide_first ? "collide-first" : "integrate-first";
}

double ParticleGenerator::max_radius() const {
    if (kind == "list") {
        double r = 0;
        for (const Disk& d : disks) r = std::max(r, d.radius);
        return r;
    }
    if (radius_kind == "uniform") return radius_max;
    if (radius_kind == "bidisperse") return std::max(radius_small, radius_large);
    return radius;
}

double Scene::max_radius() const {
    double r = 0;
    for (const ParticleGenerator& g : generators) r = std::max(r, g.max_radius());
    return r;
}

std::int64_t Scene::steps_for(double t) const { return std::llround(t / run.dt); }

}  // namespace collide
