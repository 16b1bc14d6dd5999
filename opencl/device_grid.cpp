#include "device_grid.h"

#include <algorithm>

namespace collide::opencl {
DeviceGrid::DeviceGrid(ClSession& session, std::int64_t n, std::int64_t cells)
    : session_(session), n_(n), cells_(cells) {
    const cl::Context& ctx = session.context;
    cell_of_ = cl::Buffer(ctx, CL_MEM_READ_WRITE, sizeof(cl_uint) * std::size_t(std::max<std::int64_t>(n, 1)));
    rank_ = cl::Buffer(ctx, CL_MEM_READ_WRITE, sizeof(cl_uint) * std::size_t(std::max<std::int64_t>(n, 1)));
    count_ = cl::Kernel(session.program, "grid_count");
    scan_ = cl::Kernel(session.program, "scan_blocks");
    add_offsets_ = cl::Kernel(session.program, "add_block_offsets");
    scatter_ = cl::Kernel(session.program, "grid_scatter");
    sort_cells_ = cl::Kernel(session.program, "grid_sort_cells");
    sort_cells_by_scene_index_ = cl::Kernel(session.program, "grid_sort_cells_by_scene_index");
    // The scan's work-group: 256 items, or what the device and the compiled kernel allow.
    const std::size_t kernel_max = scan_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(session.device.device);
    block_ = std::min<std::size_t>(256, kernel_max);
    // One block-sum buffer per level of the recursive scan, until one block holds everything.
    std::size_t count = std::size_t(cells) + 1;
    do {
        count = (count + block_values() - 1) / block_values();
        block_sums_.emplace_back(ctx, CL_MEM_READ_WRITE, sizeof(cl_uint) * count);
    } while (count > 1);
}

std::uint64_t DeviceGrid::work_bytes(std::int64_t n, std::int64_t cells) {
    return sizeof(cl_uint) * (2 * std::uint64_t(n) + std::uint64_t(cells) / 64 + 16);
}

void DeviceGrid::exclusive_scan(const cl::Buffer& values, std::uint32_t count, std::size_t level) {
    const std::size_t blocks = (count + block_values() - 1) / block_values();
    scan_.setArg(0, values);
    scan_.setArg(1, count);
    scan_.setArg(2, cl_uint(scan_chunk));
    scan_.setArg(3, block_sums_[level]);
    scan_.setArg(4, cl::Local(sizeof(cl_uint) * block_));
    session_.queue.enqueueNDRangeKernel(scan_, cl::NullRange, cl::NDRange(blocks * block_), cl::NDRange(block_));
    if (blocks == 1) return;
    // The block totals, scanned in turn, are the offsets each block adds.
    exclusive_scan(block_sums_[level], std::uint32_t(blocks), level + 1);
    add_offsets_.setArg(0, values);
    add_offsets_.setArg(1, count);
    add_offsets_.setArg(2, cl_uint(block_values()));
    add_offsets_.setArg(3, block_sums_[level]);
    session_.queue.enqueueNDRangeKernel(add_offsets_, cl::NullRange, cl::NDRange(count));
}

void DeviceGrid::build(const cl::Buffer& particles, const void* params, std::size_t params_size,
                       const cl::Buffer& cell_start, const cl::Buffer& sorted_index, const cl::Buffer* scene_index) {
    cl::CommandQueue& q = session_.queue;
    const std::size_t n = std::size_t(n_), cells = std::size_t(cells_);
    if (n == 0) return;
    // counts live in cell_start and are scanned in place; entry `cells` stays 0 and becomes n.
    q.enqueueFillBuffer(cell_start, cl_uint(0), 0, sizeof(cl_uint) * (cells + 1));
    count_.setArg(0, particles);
    count_.setArg(1, params_size, params);
    count_.setArg(2, cell_of_);
    count_.setArg(3, rank_);
    count_.setArg(4, cell_start);
    q.enqueueNDRangeKernel(count_, cl::NullRange, cl::NDRange(n));
    exclusive_scan(cell_start, std::uint32_t(cells + 1), 0);
    scatter_.setArg(0, cell_of_);
    scatter_.setArg(1, rank_);
    scatter_.setArg(2, cell_start);
    scatter_.setArg(3, sorted_index);
    scatter_.setArg(4, cl_int(n));
    q.enqueueNDRangeKernel(scatter_, cl::NullRange, cl::NDRange(n));
    sort_cells(cell_start, sorted_index, scene_index);
}

// The atomics of grid_count ranked each cell's disks in timing-dependent order; sorting each
// cell by scene index makes the order deterministic and the same as the host grid's.
void DeviceGrid::sort_cells(const cl::Buffer& cell_start, const cl::Buffer& sorted_index, const cl::Buffer* scene_index) {
    cl::Kernel& kernel = scene_index ? sort_cells_by_scene_index_ : sort_cells_;
    cl_uint arg = 0;
    kernel.setArg(arg++, cell_start);
    kernel.setArg(arg++, sorted_index);
    if (scene_index) kernel.setArg(arg++, *scene_index);
    kernel.setArg(arg++, cl_int(cells_));
    session_.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(std::size_t(cells_)));
}

}  // namespace collide::opencl
