// The uniform grid built on the device (kernels/grid.cl): counting sort with atomic counts,
// a work-group prefix sum, a scatter and a per-cell sort. Produces exactly the cell_start
// and sorted_index arrays that core/uniform_grid.h builds on the host.
#pragma once

#include <cstdint>
#include <vector>

#include "cl_programs.h"

namespace collide::opencl {

class DeviceGrid {
public:
    // Allocates the work buffers for n disks and `cells` cells (cell_start has cells + 1).
    DeviceGrid(ClSession& session, std::int64_t n, std::int64_t cells);

    // Fills cell_start (cells + 1 entries) and sorted_index (n entries) from the positions in
    // `particles`. `params` is the scene's StepParams (Layout<Real>::StepParams) as raw bytes:
    // it carries the box, the cell counts and n. A cell's slots come in increasing scene index:
    // the slot itself while the disks are in the scene's order (scene_index null), else
    // (*scene_index)[slot] (the disks were moved into cell order, kernels/reorder.cl).
    void build(const cl::Buffer& particles, const void* params, std::size_t params_size,
               const cl::Buffer& cell_start, const cl::Buffer& sorted_index,
               const cl::Buffer* scene_index = nullptr);

    // Device memory the grid's own work buffers take.
    static std::uint64_t work_bytes(std::int64_t n, std::int64_t cells);

private:
    void sort_cells(const cl::Buffer& cell_start, const cl::Buffer& sorted_index, const cl::Buffer* scene_index);
    void exclusive_scan(const cl::Buffer& values, std::uint32_t count, std::size_t level);
    // Values one work-group of the scan covers: each work-item scans scan_chunk of them.
    std::size_t block_values() const { return block_ * scan_chunk; }

    static constexpr std::size_t scan_chunk = 16;

    ClSession& session_;
    std::int64_t n_, cells_;
    std::size_t block_ = 1;  // work-group size of the scan
    cl::Buffer cell_of_, rank_;
    std::vector<cl::Buffer> block_sums_;  // one per scan level
    cl::Kernel count_, scan_, add_offsets_, scatter_, sort_cells_, sort_cells_by_scene_index_;
};

}  // namespace collide::opencl
