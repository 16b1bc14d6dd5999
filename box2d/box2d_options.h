// Box2dOptions: the settings of the Box2D baseline that a scene may choose in its
// [backend.box2d] table (docs/box2d-baseline.md lists them). Everything else about the Box2D
// world follows from the scene itself.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "core/scene.h"

namespace collide {

struct Box2dOptions {
    // Relative normal speed (scene units) below which Box2D drops restitution and treats a
    // contact as perfectly inelastic. Box2D's own default is 1 m/s, which makes slow
    // collisions inelastic; the baseline uses 0 so that every approaching contact bounces.
    double restitution_threshold = 0.0;
    // Sequential-impulse iterations of the velocity solver and of the non-linear position
    // solver per Box2D step (Box2D's recommended 8 and 3).
    int velocity_iterations = 8;
    int position_iterations = 3;
    // Box2D steps per scene time step dt; unset: the scene's own run.substeps.
    std::optional<int> substeps;
    // Mark every disk a "bullet": Box2D then runs continuous collision (time of impact)
    // between dynamic bodies too, not only against static ones.
    bool bullet = false;
    // Box2D metres per scene length unit; unset: chosen so the mean radius becomes 0.5 m.
    std::optional<double> length_scale;
};

// Reads scene.backend_options["box2d"] (all values are text). Throws std::runtime_error naming
// the scene, the key and what was expected on an unknown key or a bad value.
Box2dOptions parse_box2d_options(const Scene& scene);

}  // namespace collide
