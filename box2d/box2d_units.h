// Box2dUnits: the map between scene coordinates and Box2D's world.
//
// Box2D is tuned for moving bodies of 0.1-10 m: its tolerances are absolute lengths
// (b2_linearSlop = 0.005 m of allowed overlap, b2_maxLinearCorrection = 0.2 m per position
// iteration) and it caps every body's motion at b2_maxTranslation = 2 m per step. So the
// adapter rescales lengths by a factor s (Box2D metres per scene unit) and moves the origin
// to the centre of the box, where float positions have their finest spacing:
//
//     x_box2d = s (x - x_centre),      v_box2d = s v,      g_box2d = s g.
//
// Time and mass are not rescaled: Box2D's only time-dependent constant is the translation
// cap, which is per step, and its dynamics are linear in mass (density = m / (pi (s r)^2)).
#pragma once

#include <optional>
#include <string>

#include "core/scene/scene.h"

namespace collide {

struct Box2dUnits {
    double scale = 1.0;             // s: Box2D metres per scene length unit
    double centre_x = 0, centre_y = 0;

    Box2dUnits() = default;
    Box2dUnits(double s, const World& world)
        : scale(s), centre_x(0.5 * (world.xmin + world.xmax)), centre_y(0.5 * (world.ymin + world.ymax)) {}

    double to_box2d_x(double x) const { return scale * (x - centre_x); }
    double to_box2d_y(double y) const { return scale * (y - centre_y); }
    double to_box2d_length(double l) const { return scale * l; }   // also speeds, accelerations
    double from_box2d_x(double xb) const { return xb / scale + centre_x; }
    double from_box2d_y(double yb) const { return yb / scale + centre_y; }
    double from_box2d_length(double lb) const { return lb / scale; }
};

// The default scale: the mean radius becomes 0.5 m, a 1 m disk, the middle of Box2D's range.
inline double default_box2d_scale(double mean_radius) { return 0.5 / mean_radius; }

// Why Box2D cannot work with the length scale s, or nothing. Box2D computes in float, so s
// must be a finite number > 0 (the default 0.5 / r_mean overflows double to inf for a mean
// radius below 0.5 / 1.8e308 = 2.8e-309) that maps the mean radius to a length float holds as
// a normal number, [1.2e-38, 3.4e38] m. The default puts it at 0.5 m, inside Box2D's 0.1-10 m; a scale
// set in [backend.box2d] may place it anywhere float can (the `shipped` preset keeps s = 1).
// Each value handed to Box2D is then checked on its own (box2d_solver.cpp).
std::optional<std::string> box2d_scale_problem(double scale, double mean_radius, bool chosen);

}  // namespace collide
