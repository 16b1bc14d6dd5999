// The grid built by kernels (opencl/kernels/grid.cl) against core/uniform_grid.h on the same
// positions: identical cell_start and sorted_index arrays, hence identical neighbour sets,
// visited in identical order.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/uniform_grid.h"
#include "opencl/device_grid.h"
#include "opencl/opencl_solver.h"
#include "opencl/step_params.h"
#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

struct GridArrays {
    std::vector<std::uint32_t> cell_start, sorted_index;
};

template <typename Real>
GridArrays device_grid(const Scene& scene, const ParticleState<double>& s, const UniformGrid<Real>& grid) {
    using Particle = typename opencl::Layout<Real>::Particle;
    const auto device = opencl::select_device("");
    opencl::ClSession session =
        opencl::open_session(device, opencl::kernel_build_options(scene, s, sizeof(Real) == 8, device));
    const auto params = opencl::make_step_params<Real>(scene, s, grid, scene.run.dt);
    std::vector<Particle> particles(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        particles[i].x = Real(s.x[i]);
        particles[i].y = Real(s.y[i]);
        particles[i].radius = Real(s.radius[i]);
    }
    const std::size_t cells = std::size_t(grid.cell_count());
    cl::Buffer buffer(session.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof(Particle) * s.size(), particles.data());
    cl::Buffer cell_start(session.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * (cells + 1));
    cl::Buffer sorted(session.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * s.size());
    opencl::DeviceGrid builder(session, std::int64_t(s.size()), grid.cell_count());
    builder.build(buffer, &params, sizeof(params), cell_start, sorted);
    GridArrays out;
    out.cell_start.resize(cells + 1);
    out.sorted_index.resize(s.size());
    session.queue.enqueueReadBuffer(cell_start, CL_TRUE, 0, sizeof(cl_uint) * (cells + 1), out.cell_start.data());
    session.queue.enqueueReadBuffer(sorted, CL_TRUE, 0, sizeof(cl_uint) * s.size(), out.sorted_index.data());
    return out;
}

template <typename Real>
void expect_same_grid(const Scene& scene, const ParticleState<double>& s) {
    UniformGrid<Real> grid;
    grid.configure(scene.world, 2 * s.radius.front());
    std::vector<Real> x(s.x.begin(), s.x.end()), y(s.y.begin(), s.y.end());
    grid.build(x.data(), y.data(), s.size());
    const GridArrays device = device_grid<Real>(scene, s, grid);
    EXPECT_EQ(device.cell_start, grid.cell_start());
    EXPECT_EQ(device.sorted_index, grid.sorted_index());
}

// A dense random gas, plus disks that a step has carried past the walls (before clamping)
// and one NaN position: the host grid clamps them to border cells, the device must too.
ParticleState<double> crowd(const Scene& scene, std::size_t n, std::uint64_t seed) {
    ParticleState<double> s = random_gas(scene, n, 0.3, seed, /*allow_overlap=*/true);
    s.x[0] = scene.world.xmin - 0.1;
    s.y[1] = scene.world.ymax + 0.05;
    s.x[2] = scene.world.xmax;  // exactly on the upper wall
    s.y[3] = std::numeric_limits<double>::quiet_NaN();
    return s;
}

TEST(OpenclGrid, DeviceGridEqualsHostGridReflecting) {
    const Scene scene = box_scene(30, 17);
    const auto s = crowd(scene, 5000, 21);  // more cells and disks than one scan block
    expect_same_grid<float>(scene, s);
    expect_same_grid<double>(scene, s);
}

TEST(OpenclGrid, DeviceGridEqualsHostGridPeriodic) {
    const Scene scene = box_scene(12, 40, Boundary::periodic);
    expect_same_grid<float>(scene, crowd(scene, 2000, 22));
}

TEST(OpenclGrid, DeviceGridEqualsHostGridWithManyCells) {
    // 333 x 333 cells: the prefix sum spans many work-group blocks (4096 values each), so
    // the recursive scan of the block sums and the offsets are exercised.
    const Scene scene = box_scene(200, 200);
    expect_same_grid<float>(scene, crowd(scene, 20000, 24));
}

TEST(OpenclGrid, DeviceGridEqualsHostGridWithOneCell) {
    // Every disk in one cell: the per-cell sort has the most to do.
    const Scene scene = box_scene(1, 1);
    ParticleState<double> s = random_gas(scene, 300, 0.45, 23, /*allow_overlap=*/true);
    expect_same_grid<float>(scene, s);
}

}  // namespace
}  // namespace collide::test
