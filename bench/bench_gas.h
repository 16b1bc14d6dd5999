// The benchmarks' standard gas (the `throughput`, `features`, `bandwidth` and `opencl`
// suites): core's one gas builder (core/scene/gas_scene.h) with the benchmarks' choices, so that a
// benchmark at N = 10^6 does not wait for a rejection sampler.
#pragma once

#include <cstdint>

#include "core/scene/gas_scene.h"

namespace collide::bench {

// N disks of radius 0.5 and unit mass at area fraction `phi` (box edge L = sqrt(N pi r^2 / phi)),
// placed on a square lattice with a random jitter that keeps them apart, with velocities
// uniform in [-1, 1]^2. The disks are listed in a random order, as a random generator would
// give them (a lattice listing would already be sorted by cell, which flatters the memory
// behaviour of every backend). Collide-first rule, dt = 0.01 (a disk moves at most 3% of its
// radius per step), e = 1, reflecting walls, no forces.
inline GasCase bench_gas(std::int64_t n, double phi = 0.3, std::uint64_t seed = 1) {
    GasSceneSpec spec;
    spec.count = n;
    spec.area_fraction = phi;
    spec.seed = seed;
    spec.placement = GasPlacement::lattice;
    spec.jitter = spec.shuffle = spec.uniform_velocities = true;
    spec.run.dt = 0.01;
    spec.run.order = StepOrder::collide_first;
    GasCase gas = make_gas(spec);
    gas.scene.name = "bench_gas";
    gas.scene.description = "benchmark gas, area fraction " + std::to_string(phi);
    return gas;
}

}  // namespace collide::bench
