// grid = "group" (kernels/group_steps.cl): one work-group runs many steps per launch. It must
// give bitwise the state of the per-step kernels and of `cpu` (the same grid order, the same
// operations), whatever the number of passes in a launch (odd counts leave the state in the
// other buffer), and be the default for small scenes only.
#include <gtest/gtest.h>

#include <string>

#include "core/run_driver.h"
#include "opencl_test_scenes.h"
#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

constexpr int steps = 40;

BackendOptions grid_options(const std::string& real, const std::string& grid) {
    BackendOptions options;
    options.real = real;
    options.extra["grid"] = grid;
    return options;
}

// cpu's cell path (skin 0), the search opencl mirrors.
BackendOptions cpu_cell_path() { return BackendOptions{0, "", "", {{"skin", "0"}}}; }

RunResult run_with(const std::string& name, const OpenclCase& c, const BackendOptions& options) {
    auto solver = backend(name).create(options);
    return run_scene(c.scene, *solver, c.initial);
}

void expect_same_state(const ParticleState<double>& a, const ParticleState<double>& b) {
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.vx, b.vx);
    EXPECT_EQ(a.vy, b.vy);
}

TEST(OpenclGroup, GroupLaunchesEqualThePerStepKernelsBitwise) {
    for (const char* real : {"float", "double"})
        for (const auto& c : opencl_cases(steps)) {
            SCOPED_TRACE(std::string(real) + ", " + c.name);
            const RunResult per_step = run_with("opencl", c, grid_options(real, "host"));
            const RunResult group = run_with("opencl", c, grid_options(real, "group"));
            expect_same_state(group.final_state, per_step.final_state);
            EXPECT_EQ(group.stats.contacts, per_step.stats.contacts);
            EXPECT_EQ(group.stats.steps, per_step.stats.steps);
            EXPECT_GT(group.stats.contacts, 0);
        }
}

TEST(OpenclGroup, GroupLaunchesEqualCpuBitwise) {
    for (const auto& c : opencl_cases(steps)) {
        SCOPED_TRACE(c.name);
        // opencl mirrors cpu's cell path (skin 0): the pair list adds contacts in its own order.
        const RunResult cpu = run_with("cpu", c, cpu_cell_path());
        const RunResult group = run_with("opencl", c, grid_options("float", "group"));
        expect_same_state(group.final_state, cpu.final_state);
        EXPECT_EQ(group.stats.contacts, cpu.stats.contacts);
    }
}

// Advances of 1, 2, 3, ... steps (odd and even numbers of passes per launch, the
// integrate-first case 4 passes per step) reach the state of one advance over all of them.
TEST(OpenclGroup, UnevenAdvancesReachTheStateOfOneAdvance) {
    for (const auto& c : opencl_cases(steps)) {
        SCOPED_TRACE(c.name);
        const BackendOptions options = grid_options("float", "group");
        auto whole = backend("opencl").create(options);
        whole->load(c.scene, c.initial);
        whole->advance_to(c.scene.run.duration);
        auto pieces = backend("opencl").create(options);
        pieces->load(c.scene, c.initial);
        std::int64_t done = 0;
        for (std::int64_t k = 1; done < steps; ++k) {
            done = std::min<std::int64_t>(done + k, steps);
            pieces->advance_to(double(done) * c.scene.run.dt);
        }
        ParticleState<double> a, b;
        whole->read_state(a);
        pieces->read_state(b);
        expect_same_state(b, a);
        EXPECT_EQ(pieces->stats().steps, whole->stats().steps);
        EXPECT_EQ(pieces->stats().contacts, whole->stats().contacts);
    }
}

std::string default_grid(std::int64_t disks) {
    Scene scene = box_scene(200, 200);
    scene.run.dt = 1e-3;
    auto solver = backend("opencl").create({});
    solver->load(scene, random_gas(scene, disks, 0.1, 5));
    return solver->provenance().at("grid");
}

TEST(OpenclGroup, DefaultIsGroupForSmallScenesOnly) {
    EXPECT_EQ(default_grid(2), "group");
    EXPECT_EQ(default_grid(4096), "group");
    EXPECT_NE(default_grid(4097), "group");
}

TEST(OpenclGroup, GroupRunsTheSceneOrderWithoutReordering) {
    const OpenclCase c = opencl_cases(steps).front();
    auto solver = backend("opencl").create(grid_options("float", "group"));
    solver->load(c.scene, c.initial);
    EXPECT_EQ(solver->provenance().at("sort_interval"), "0");
}

}  // namespace
}  // namespace collide::test
