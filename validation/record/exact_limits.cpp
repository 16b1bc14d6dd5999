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
    const double drift = conservation_rounding(epsilon, scale.collisions.value_or(collisions_without_reference));
    t.momentum_drift = drift;
    t.energy_drift = drift;
    if (const auto depth = contact_rounding(epsilon, scale)) {
        t.max_overlap = *depth;
        t.mean_overlap = *depth;
        t.overlap_beyond_step = *depth;  // at most the depth itself
        t.wall_penetration = 2 * *depth;  // relative to a radius, not to a contact distance
    }
}

double conservation_rounding(double epsilon, std::int64_t collisions) {
    // + 1: the metric's own rounding of the sums, present with no collision at all.
    return conservation_epsilons_per_collision * epsilon * double(std::max<std::int64_t>(collisions, 0) + 1);
}

std::optional<double> contact_rounding(double epsilon, const RoundingScale& scale) {
    if (!(scale.smallest_radius > 0 && scale.coordinate > 0)) return std::nullopt;
    return position_epsilons * epsilon * scale.coordinate / (2 * scale.smallest_radius);
}

}  // namespace collide::validation
