#include "box2d_units.h"

#include <cmath>
#include <limits>

#include "core/numerics/number_text.h"

namespace collide {

std::optional<std::string> box2d_scale_problem(double scale, double mean_radius, bool chosen) {
    const std::string s = "length scale s = " + round_trip_text(scale) +
                          (chosen ? " ([backend.box2d] length_scale)"
                                  : " (0.5 / mean radius " + round_trip_text(mean_radius) + ")");
    if (!(std::isfinite(scale) && scale > 0))
        return s + " is not a finite number > 0: Box2D's metres cannot be computed from it";
    const double mapped = scale * mean_radius;
    constexpr double lo = std::numeric_limits<float>::min(), hi = std::numeric_limits<float>::max();
    if (!(mapped >= lo && mapped <= hi))
        return s + " maps the mean radius to " + round_trip_text(mapped) +
               " m, outside float's normal range [1.2e-38, 3.4e+38] in which Box2D computes";
    return std::nullopt;
}

}  // namespace collide
