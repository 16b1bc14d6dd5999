// The crystal box of Li et al. (J. Chem. Phys. 157, 234111 (2022)): N = columns x rows equal
// disks (diameter 1) on a hexagonal lattice that fills a periodic box of aspect
// columns : rows sqrt(3)/2 exactly, at packing fraction eta. The lattice spacing a follows from
// eta = N pi (1/2)^2 / (columns a x rows a sqrt(3)/2). N = 870 is 29 x 30.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "core/scene/scene.h"

namespace collide::bench {

// The scene generator's lattice that fills a periodic box (`fill_box`, core/scene/filled_lattice.h),
// as the physics suite's li2022_*_crystal scenes use it; velocities Maxwell at kT = 1 (unit
// mass) from the scene's seed, the centre of mass at rest.
inline Scene crystal_box(int columns, int rows, double eta, std::uint64_t seed) {
    const double spacing = std::sqrt(M_PI / (2 * std::sqrt(3.0) * eta)), row_height = spacing * std::sqrt(3.0) / 2;
    Scene s;
    s.name = "crystal_box_" + std::to_string(columns * rows);
    s.description = "hexagonal crystal box " + std::to_string(columns) + " x " + std::to_string(rows) + ", eta " + std::to_string(eta);
    s.seed = seed;
    s.world = World{0, 0, columns * spacing, rows * row_height, Boundary::periodic};
    ParticleGenerator g;
    g.kind = "lattice";
    g.lattice = "hexagonal";
    g.fill_box = true;
    g.columns = columns;
    g.count = std::int64_t(columns) * rows;
    g.radius = 0.5;
    g.mass = 1.0;
    g.velocity_kind = "maxwell";
    g.temperature = 1.0;
    s.generators.push_back(g);
    return s;
}

}  // namespace collide::bench
