// How much memory a run of a scene needs, estimated from the scene alone before a single disk
// is generated. A scene of 2 x 10^9 disks is then refused at once with the numbers, instead
// of being killed by the operating system minutes into generation (or swapping the machine
// to a standstill). docs/scenes.md ("Bad input") gives the formula.
#pragma once

#include <cstdint>

#include "core/scene/scene.h"

namespace collide {

// Bytes per disk, by what holds them at the peak of a run:
//   3 x 7 x 8  three double states of 7 arrays (x, y, vx, vy, radius, mass, inv_mass): the
//              initial state, the solver's own copy, the state read back for the metrics
//   4 x 8      the stepping rules' accumulated corrections (dx, dy, dvx, dvy), double
//   7 x 4      a float backend's copy of the state (cpu, opencl)
//   2 x 2 x 4  two uniform grids (the solver's and the metrics'): each disk's cell and its
//              slot in the cell-sorted order, 32-bit each
//   168        generation scratch: the placement cell list (x, y, r, link and about 4 cells
//              per disk, 8 B each) and two temporary copies of the disk records (6 doubles)
// Box2D keeps far more per body (its own body, fixture and contact objects): for the box2d
// backend this is a lower bound.
constexpr double bytes_per_disk = 3 * 7 * 8 + 4 * 8 + 7 * 4 + 2 * 2 * 4 + 168;  // 412
// Bytes per grid cell: two grids, each with a 32-bit first slot and fill pointer per cell.
constexpr double bytes_per_grid_cell = 2 * 2 * 4;
// The grids never use more cells than this (core/uniform_grid.h caps them).
constexpr double max_grid_cells = double(std::int64_t(1) << 26);
// A scene is refused when its estimate exceeds this share of the machine's physical memory;
// the rest is left to the operating system, the output buffers and other programs.
constexpr double max_memory_share = 0.5;

struct MemoryEstimate {
    std::int64_t disks = 0;
    double grid_cells = 0;  // cells of side 2 r_max over the box, at most max_grid_cells
    double bytes() const { return double(disks) * bytes_per_disk + grid_cells * bytes_per_grid_cell; }
};

MemoryEstimate estimate_memory(const Scene& scene);

// Physical memory of this machine: sysconf(_SC_PHYS_PAGES) x sysconf(_SC_PAGESIZE), or
// infinity where the system cannot tell (then no scene is refused for its size).
double physical_memory_bytes();

// Throws SceneError when the estimate exceeds max_memory_share x physical_bytes, naming the
// [[particles]] block (file and line) that takes the scene past the limit, the requested N,
// the estimate in GiB and the physical memory.
void check_memory(const Scene& scene, double physical_bytes = physical_memory_bytes());

}  // namespace collide
