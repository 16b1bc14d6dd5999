// The benchmark scene: a gas of N equal disks at a given area fraction in a square box,
// built in code so that a benchmark at N = 10^6 does not wait for a rejection sampler.
#pragma once

#include <cstdint>

#include "core/particle_state.h"
#include "core/scene.h"

namespace collide::bench {

struct GasCase {
    Scene scene;
    ParticleState<double> initial;
};

// N disks of radius 0.5 and unit mass at area fraction `phi` (box edge L = sqrt(N pi r^2 / phi)),
// placed on a square lattice with a random jitter that keeps them apart, with velocities
// uniform in [-1, 1]^2. The disks are then listed in a random order, as a random generator
// would give them (a lattice listing would already be sorted by cell, which flatters the
// memory behaviour of every backend). Collide-first rule, dt = 0.01 (a disk moves at most
// 3% of its radius per step), e = 1, reflecting walls, no forces.
GasCase gas_case(std::int64_t n, double phi = 0.3, std::uint64_t seed = 1);

}  // namespace collide::bench
