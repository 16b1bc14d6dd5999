#include "overlap_pairs.h"

#include <algorithm>
#include <cmath>

namespace collide::view {
namespace {

// The shortest displacement along a periodic axis of length `length`.
double minimum_image(double d, double length) { return d - length * std::round(d / length); }

}  // namespace

void OverlapFinder::find(const World& world, const ParticleState<double>& s, std::vector<OverlapMark>& out) {
    out.clear();
    const std::size_t n = s.size();
    if (n < 2) return;
    const double r_max = *std::max_element(s.radius.begin(), s.radius.end());
    grid_.configure(world, 2 * r_max);
    grid_.build(s.x.data(), s.y.data(), n);
    const bool periodic = world.boundary == Boundary::periodic;
    for (std::size_t i = 0; i < n; ++i) {
        grid_.for_each_candidate(s.x[i], s.y[i], [&](std::uint32_t j) {
            if (j <= i) return;  // each pair once
            double dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
            if (periodic) {
                dx = minimum_image(dx, world.width());
                dy = minimum_image(dy, world.height());
            }
            const double contact = s.radius[i] + s.radius[j];
            if (dx * dx + dy * dy < contact * contact)
                out.push_back({s.x[i] + dx / 2, s.y[i] + dy / 2, std::min(s.radius[i], s.radius[j])});
        });
    }
}

}  // namespace collide::view
