// The one gas built in code, without a scene file: for benchmarks and tests that need
// "N disks at area fraction phi" at many sizes.
//
//   GasSceneSpec spec;
//   spec.count = 100000;
//   spec.area_fraction = 0.3;
//   Scene scene = make_gas_scene(spec);
//   ParticleState<double> state = generate_initial_state(scene);  // core/scene/scene_loader.h
//
// or, for the scene and its initial state in one (either placement):
//
//   GasCase gas = make_gas(spec);
//
// The box is a square (or width/height = aspect) sized so that the disks cover the area
// fraction phi = N pi r^2 / (L_x L_y). Two placements:
//  - random (the default): one [[particles]] gas block, random sequential addition with
//    Maxwell-Boltzmann velocities, exactly as a scene file with the same values would give;
//    it jams near phi = 0.547.
//  - lattice: a square lattice of ceil(sqrt(N)) columns (square boxes only), which holds up to
//    phi = pi/4; a dense fluid is made from it by running it for a few collisions per disk
//    ("melting", as `collide bench event` does). Options: a random jitter, a random listing
//    order, uniform velocities, the centre-of-mass drift removed (see GasSceneSpec).
#pragma once

#include <cstdint>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide {

enum class GasPlacement { random, lattice };

struct GasSceneSpec {
    std::int64_t count = 1000;       // N, number of disks
    double area_fraction = 0.3;      // phi; random placement jams near 0.547, the lattice holds pi/4
    double radius = 0.5;             // every disk has this radius
    double mass = 1.0;               // and this mass
    double temperature = 1.0;        // kT of the Maxwell-Boltzmann velocities
    double aspect = 1.0;             // box width / height (1 for the lattice)
    Boundary boundary = Boundary::reflect;
    std::uint64_t seed = 1;
    RunSettings run;                 // duration, dt, ... (defaults of RunSettings)
    GasPlacement placement = GasPlacement::random;

    // Lattice placement only. Its random numbers come from std::mt19937_64(seed), drawn in
    // this order: the listing order (if shuffled), then per disk its jitter (x, y) and its
    // velocity (x, y).
    // Each coordinate shifted uniformly by up to a quarter of the free gap between lattice
    // neighbours (spacing - 2 r), so that no two disks touch.
    bool jitter = false;
    // The disks listed in a random order, as a random generator would list them: a lattice
    // listing is already sorted by cell, which flatters the memory behaviour of every backend.
    bool shuffle = false;
    // Velocity components uniform in [-uniform_speed, uniform_speed] (temperature unused)
    // instead of Gaussian with variance kT/m.
    bool uniform_velocities = false;
    double uniform_speed = 1.0;
    // Subtract the mean velocity, so that the total momentum is zero (a periodic box keeps it).
    bool remove_drift = false;
};

// A scene and its initial state.
struct GasCase {
    Scene scene;
    ParticleState<double> initial;
};

// The scene of a randomly placed gas (the state comes from generate_initial_state). Throws
// SceneError for a count < 1, a non-positive radius, mass or aspect, an area fraction outside
// (0, 0.547), or a spec asking for the lattice placement.
Scene make_gas_scene(const GasSceneSpec& spec);

// Scene and initial state, for either placement. The lattice refuses an area fraction outside
// (0, pi/4) and an aspect other than 1. A lattice gas's scene has no generators: its state
// exists only here, so reload it from this function, not from the scene.
GasCase make_gas(const GasSceneSpec& spec);

}  // namespace collide
