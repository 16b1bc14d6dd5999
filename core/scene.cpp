#include "scene.h"

#include <cmath>

namespace collide {

const char* to_string(Boundary b) { return b == Boundary::reflect ? "reflect" : "periodic"; }

const char* to_string(StepOrder o) {
    return o == StepOrder::collide_first ? "collide-first" : "integrate-first";
}

std::int64_t Scene::steps_for(double t) const { return std::llround(t / run.dt); }

}  // namespace collide
