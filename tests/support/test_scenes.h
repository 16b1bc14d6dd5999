// Scenes and states built in code for tests, independent of the scene-file loader, so a
// test of a solver does not also test the parser.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide::test {

struct DiskSpec {
    double x, y, vx, vy, radius, mass;
    bool stone = false;
};

// A box [0, width] x [0, height] with default physics (e = 1, no forces) and run settings.
Scene box_scene(double width, double height, Boundary boundary = Boundary::reflect);

ParticleState<double> make_state(const std::vector<DiskSpec>& disks);

// n disks of radius r at random non-overlapping positions with random velocities in
// [-1, 1]^2 and unit masses (simple rejection sampling with std::mt19937_64 and a seed).
ParticleState<double> random_gas(const Scene& scene, std::size_t n, double radius, std::uint64_t seed,
                                 bool allow_overlap = false);

// Number of overlapping pairs by brute force over all pairs (minimum image in a periodic
// world). Pairs closer than (r_i + r_j)(1 - 1e-12) count: disks placed exactly touching do not.
int brute_force_overlapping_pairs(const Scene& scene, const ParticleState<double>& s);

// Absolute path of a file in the source tree's data/scenes/.
std::string scene_file(const std::string& relative);

}  // namespace collide::test
