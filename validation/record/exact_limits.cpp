#include "validation/record/exact_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide::validation {

double machine_epsilon(bool single_precision) {
    return single_precision ? double(std::numeric_limits<float>::epsilon()) : std::numeric_limits<double>::epsilon();
}

RoundingScale rounding_scale(const CaseResult& result, const Scene& scene, const CaseResult* reference) {
    RoundingScale s;
    if (reference && reference->finished()) s.collisions = reference->contacts;
    const World& w = scene.world;
    s.coordinate = std::max({std::fabs(w.xmin), std::fabs(w.xmax), std::fabs(w.ymin), std::fabs(w.ymax)});
    if (!result.initial.radius.empty())
        s.smallest_radius = *std::min_element(result.initial.radius.begin(), result.initial.radius.end());
    return s;
}

void apply_exact_limits(Tolerances& t, double epsilon, const RoundingScale& scale) {
    // + 1: the metric's own rounding of the sums, present with no collision at all.
    const std::int64_t collisions = scale.collisions.value_or(collisions_without_reference);
    const double drift = conservation_epsilons_per_collision * epsilon * double(collisions + 1);
    t.momentum_drift = drift;
    t.energy_drift = drift;
    if (scale.smallest_radius > 0 && scale.coordinate > 0) {
        const double depth = position_epsilons * epsilon * scale.coordinate;  // absolute, in length
        t.max_overlap = depth / (2 * scale.smallest_radius);
        t.mean_overlap = t.max_overlap;
        t.wall_penetration = depth / scale.smallest_radius;
    }
}

}  // namespace collide::validation
