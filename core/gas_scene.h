// A gas scene built in code, without a scene file: for benchmarks and tests that need
// "N disks at area fraction phi" at many sizes.
//
//   GasSceneSpec spec;
//   spec.count = 100000;
//   spec.area_fraction = 0.3;
//   Scene scene = make_gas_scene(spec);
//   ParticleState<double> state = generate_initial_state(scene);  // core/scene_loader.h
//
// The box is a square (or width/height = aspect) sized so that the disks cover the area
// fraction phi = N pi r^2 / (L_x L_y); the disks are one [[particles]] gas block with
// Maxwell-Boltzmann velocities, exactly as a scene file with the same values would give.
#pragma once

#include <cstdint>

#include "scene.h"

namespace collide {

struct GasSceneSpec {
    std::int64_t count = 1000;       // N, number of disks
    double area_fraction = 0.3;      // phi; random sequential addition jams near 0.547
    double radius = 0.5;             // every disk has this radius
    double mass = 1.0;               // and this mass
    double temperature = 1.0;        // kT of the Maxwell-Boltzmann velocities
    double aspect = 1.0;             // box width / height
    Boundary boundary = Boundary::reflect;
    std::uint64_t seed = 1;
    RunSettings run;                 // duration, dt, ... (defaults of RunSettings)
};

// Throws SceneError for a count < 1, a non-positive radius, mass or aspect, or an area
// fraction outside (0, 0.547).
Scene make_gas_scene(const GasSceneSpec& spec);

}  // namespace collide
