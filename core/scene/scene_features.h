// SceneFeatures: what a scene uses of the optional physics (walls, gravity, damping, friction,
// restitution below 1, stones, unequal radii), worked out once. Every consumer reads it:
//   - the `cpu` backend picks the loop instantiation that leaves out what is unused
//     (cpu/feature_set.h);
//   - the `opencl` backend turns it into the kernels' -D flags (opencl/step_params.h);
//   - the event solvers' supports() say which scenes they cannot run (reference/);
//   - validation decides which checks apply and why (validation/judge/applicability.h).
#pragma once

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide {

struct SceneFeatures {
    bool reflecting_walls = false;  // else periodic boundaries
    bool gravity = false, damping = false, friction = false;
    double restitution = 1, wall_restitution = 1;
    bool stones = false;          // some disk is a kinematic stone (inverse mass 0)
    bool moving_stones = false;   // some stone starts with a velocity (it does work on the disks)
    bool uniform_radius = true;   // every disk has the same radius (one contact distance)
    double area_fraction = 0;     // sum of pi r^2 over the box's area

    bool periodic() const { return !reflecting_walls; }
};

// What the scene file itself states: boundaries, forces, restitution, and stones declared by a
// generator. The radii and the area fraction need the generated disks (below); here they keep
// their defaults.
SceneFeatures scene_features(const Scene& scene);

// The scene's features with its generated initial state: stones, moving stones, uniform radius
// and area fraction as the disks are.
SceneFeatures scene_features(const Scene& scene, const ParticleState<double>& initial);

// True if the state holds disks and all have the same radius.
bool uniform_radius(const ParticleState<double>& state);

}  // namespace collide
