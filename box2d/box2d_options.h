// Box2dOptions: the settings of the Box2D baseline that a scene may choose in its
// [backend.box2d] table (docs/box2d-baseline.md lists them). Everything else about the Box2D
// world follows from the scene itself.
//
// Two presets give every setting a value; any key set beside `preset` replaces that one value:
//   "tuned"   (the default) the best Box2D can do on hard disks: every contact bounces, disks
//             scaled to Box2D's favourite size, no sleeping, no spin;
//   "shipped" Box2D 2.4 as a user gets it: each setting is read from a freshly constructed
//             b2World, b2BodyDef and b2FixtureDef, scene units are metres 1:1.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "core/scene/scene.h"

namespace collide {

struct Box2dOptions {
    std::string preset = "tuned";
    // Relative normal speed below which Box2D drops restitution and treats a contact as
    // perfectly inelastic. Set: in scene units (tuned: 0, so every approaching contact
    // bounces). Unset: Box2D's own default (b2FixtureDef, 1 m/s), in Box2D's metres per second.
    std::optional<double> restitution_threshold = 0.0;
    // Sequential-impulse iterations of the velocity solver and of the non-linear position
    // solver per Box2D step (the Box2D 2.4 manual recommends 8 and 3).
    int velocity_iterations = 8;
    int position_iterations = 3;
    // Box2D steps per scene time step dt; unset: the scene's own run.substeps.
    std::optional<int> substeps;
    // Mark every disk a "bullet": Box2D then runs continuous collision (time of impact)
    // between dynamic bodies too, not only against static ones.
    bool bullet = false;
    // Box2D metres per scene length unit; unset: chosen so the mean radius becomes 0.5 m.
    std::optional<double> length_scale;
    // Bodies that stay slow for b2_timeToSleep (0.5 s) stop being simulated.
    bool sleeping = false;
    // Re-use last step's contact impulses as the solver's starting guess.
    bool warm_starting = true;
    // Time of impact of dynamic bodies against static ones (walls, stones).
    bool continuous = true;
    // No rotation: the model's disks carry no spin, and friction would feed energy into it.
    bool fixed_rotation = true;
};

// The preset called `name` ("tuned" or "shipped"); nullopt for any other name.
std::optional<Box2dOptions> box2d_preset(const std::string& name);

// The largest iteration or sub-step count a key accepts.
inline constexpr int max_box2d_iterations = 1000000;

// Reads scene.backend_options["box2d"] through core/scene/option_reader.h: the preset, then every
// other key on top of it. Throws BackendOptionError naming where the key was set, the key and
// what was expected on an unknown key or a bad value.
Box2dOptions parse_box2d_options(const Scene& scene);

}  // namespace collide
