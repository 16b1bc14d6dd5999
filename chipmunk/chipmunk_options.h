// ChipmunkOptions: the settings of the Chipmunk2D adapter that a scene may choose in its
// [backend.chipmunk] table (docs/engines.md lists them with their reasons). Everything else
// about the cpSpace follows from the scene itself.
//
// Two presets give every setting a value; any key set beside `preset` replaces that one value:
//   "tuned"   (the default) the best Chipmunk does on hard disks: no collision slop, each
//             contact's restitution and friction set to the scene's (not Chipmunk's product
//             of the two shapes' values), no spin;
//   "shipped" Chipmunk 7 as a user gets it: every space setting read from a fresh cpSpace,
//             shapes given the scene's elasticity and friction (which Chipmunk multiplies),
//             disks with the moment of inertia of a solid circle, scene units taken 1:1.
#pragma once

#include <optional>
#include <string>

#include "core/scene/scene.h"

namespace collide {

struct ChipmunkOptions {
    std::string preset = "tuned";
    // Overlap Chipmunk allows before it pushes shapes apart, in scene length units. Chipmunk's
    // default, 0.1, assumes its pixel-sized units (bodies of tens of units): it is 10 % of a
    // unit radius, 20 times a radius of 0.005. Tuned: 0, every overlap is corrected.
    double collision_slop = 0;
    // Fraction of an overlap left uncorrected after one second (Chipmunk: pow(1 - 0.1, 60),
    // 10 % per step at 60 Hz). The correction moves positions through a separate bias velocity
    // that is discarded after the step, so it does not feed the kinetic energy.
    double collision_bias = 0;  // both presets: cpSpaceNew's value
    // Sequential-impulse iterations per step (Chipmunk's default: 10).
    int iterations = 10;
    // Chipmunk steps per scene time step dt; unset: the scene's own run.substeps.
    std::optional<int> substeps;
    // "scene": a contact's restitution and friction are the scene's (e between disks, the wall
    // restitution at the walls, friction 0 at the smooth walls), set in a pre-solve callback.
    // "product": Chipmunk's own rule, e_a * e_b of the two shapes (so e^2 between disks).
    std::string combine = "scene";
    // No rotation (infinite moment of inertia): the model's disks carry no spin.
    bool fixed_rotation = true;
};

// The preset called `name` ("tuned" or "shipped"); nullopt for any other name.
std::optional<ChipmunkOptions> chipmunk_preset(const std::string& name);

inline constexpr int max_chipmunk_iterations = 1000000;

// Reads scene.backend_options["chipmunk"] through core/scene/option_reader.h: the preset, then
// every other key on top of it. Throws BackendOptionError naming where the key was set, the key
// and what was expected on an unknown key or a bad value.
ChipmunkOptions parse_chipmunk_options(const Scene& scene);

}  // namespace collide
