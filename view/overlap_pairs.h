// The overlapping pairs of a state (|x_i - x_j| < r_i + r_j), for the red marks of a frame.
// The metrics count and measure overlaps but do not list them; the search is the same
// (core's UniformGrid, cells of at least 2 r_max, 3x3 neighbourhood, minimum image when periodic).
#pragma once

#include <cstdint>
#include <vector>

#include "core/particle_state.h"
#include "core/scene.h"
#include "core/uniform_grid.h"

namespace collide::view {

struct OverlapMark {
    double x = 0, y = 0;  // the midpoint of the two centres (through the wrap when periodic)
    double radius = 0;    // the smaller disk's radius, to size the mark
};

class OverlapFinder {
public:
    // Appends one mark per overlapping pair to `out` (cleared first).
    void find(const World& world, const ParticleState<double>& state, std::vector<OverlapMark>& out);

private:
    UniformGrid<double> grid_;
};

}  // namespace collide::view
