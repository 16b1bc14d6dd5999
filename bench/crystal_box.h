// The crystal box of Li et al. (J. Chem. Phys. 157, 234111 (2022)): N = columns x rows equal
// disks (diameter 1) on a hexagonal lattice that fills a periodic box of aspect
// columns : rows sqrt(3)/2 exactly, at packing fraction eta. The lattice spacing a follows from
// eta = N pi (1/2)^2 / (columns a x rows a sqrt(3)/2). N = 870 is 29 x 30.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "core/scene/scene.h"

namespace collide::bench {

// The lattice is listed disk by disk (a "list" block): the scene generator's hexagonal lattice
// must fit inside the box without wrapping, which a lattice that fills a periodic box does not.
// Velocities: Maxwell at kT = 1 (unit mass), drawn with std::mt19937_64(seed).
inline Scene crystal_box(int columns, int rows, double eta, std::uint64_t seed) {
    const double spacing = std::sqrt(M_PI / (2 * std::sqrt(3.0) * eta)), row_height = spacing * std::sqrt(3.0) / 2;
    Scene s;
    s.name = "crystal_box_" + std::to_string(columns * rows);
    s.description = "hexagonal crystal box " + std::to_string(columns) + " x " + std::to_string(rows) + ", eta " + std::to_string(eta);
    s.seed = seed;
    s.world = World{0, 0, columns * spacing, rows * row_height, Boundary::periodic};
    ParticleGenerator g;
    g.kind = "list";
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> maxwell(0.0, 1.0);
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const double x = (column + 0.25 + 0.5 * (row % 2)) * spacing, y = (row + 0.5) * row_height;
            const double vx = maxwell(rng), vy = maxwell(rng);
            g.disks.push_back({x, y, vx, vy, 0.5, 1.0, false, 0});
        }
    s.generators.push_back(g);
    return s;
}

}  // namespace collide::bench
