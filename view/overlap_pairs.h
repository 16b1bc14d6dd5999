// The overlapping pairs of a state (|x_i - x_j| < r_i + r_j): the red marks of a frame, and the
// HUD's overlap figures from the same list (one pair search per frame). The search is core's
// UniformGrid (cells of at least 2 r_max, 3x3 neighbourhood, minimum image when periodic), read
// in cell order: positions are gathered into slot order once, so that each disk's neighbours
// lie in a few contiguous slot ranges, and the slots are shared among threads.
#pragma once

#include <cstdint>
#include <vector>

#include "core/metrics.h"
#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "core/uniform_grid.h"

namespace collide::view {

struct OverlapMark {
    double x = 0, y = 0;  // the midpoint of the two centres (through the wrap when periodic)
    double radius = 0;    // the smaller disk's radius, to size the mark
    double depth = 0;     // (r_i + r_j - d) / (r_i + r_j), as in the metrics
    std::uint32_t i = 0, j = 0;  // the two disks, as indices of the state
};

class OverlapFinder {
public:
    // Fills `out` with one mark per overlapping pair of finite disks, in a fixed order for any
    // thread count. threads <= 0: OpenMP's default.
    void find(const World& world, const ParticleState<double>& state, std::vector<OverlapMark>& out,
              int threads = 0);

private:
    void gather_in_slot_order(const ParticleState<double>& state, int threads);
    void find_from_slots(std::size_t begin, std::size_t end, std::vector<OverlapMark>& out) const;

    World world_;
    UniformGrid<double> grid_;
    std::vector<double> x_, y_, radius_;            // the disks in slot (cell) order
    std::vector<std::vector<OverlapMark>> chunks_;  // each chunk's marks, joined in order
};

// compute_metrics' figures for a state whose overlapping pairs are `overlaps`: the per-disk sums
// and, from the list, the overlap fields through core's OverlapTally (no second pair search).
Metrics frame_metrics(const Scene& scene, const ParticleState<double>& state, double time,
                      const std::vector<OverlapMark>& overlaps);

}  // namespace collide::view
