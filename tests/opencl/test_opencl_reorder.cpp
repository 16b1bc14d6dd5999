// Moving the disks into cell order (option sort_interval, kernels/reorder.cl) changes where each
// disk lives in device memory, never a result: every cell lists its disks by scene index whether
// or not they moved, so each disk meets the same neighbours in the same order and every sum
// rounds the same way; read_state hands the state back in the scene's order.
#include <gtest/gtest.h>

#include <string>

#include "core/numerics/phase_timer.h"
#include "core/run_driver.h"
#include "opencl_test_scenes.h"
#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

constexpr int steps = 50;

BackendOptions options_for(const std::string& real, const std::string& grid, const std::string& sort_interval) {
    BackendOptions options;
    options.real = real;
    options.extra["grid"] = grid;
    options.extra["sort_interval"] = sort_interval;
    return options;
}

RunResult run_opencl(const OpenclCase& c, const BackendOptions& options) {
    auto solver = backend("opencl").create(options);
    return run_scene(c.scene, *solver, c.initial);
}

// A gas of 2000 disks listed in random order (random_gas draws each position independently):
// a reorder by cell permutes nearly every disk, and the scene spans many cells.
OpenclCase random_listing_gas() {
    Scene scene = box_scene(50, 50);
    scene.run.dt = 2e-3;
    scene.run.duration = scene.run.dt * steps;
    scene.run.output_interval = scene.run.duration;
    return {"random listing", scene, random_gas(scene, 2000, 0.4, 31)};
}

std::vector<OpenclCase> reorder_cases() {
    std::vector<OpenclCase> cases = opencl_cases(steps);  // periodic, integrate-first, polydisperse + stones
    cases.push_back(random_listing_gas());
    return cases;
}

// Exact equality in double and in float alike: no tolerance is needed because the arithmetic of
// each disk is the same sequence of operations on the same operands.
TEST(OpenclReorder, ReorderOnAndOffGiveBitwiseIdenticalRuns) {
    for (const char* real : {"double", "float"})
        for (const char* grid : {"host", "device"})
            for (const auto& c : reorder_cases()) {
                SCOPED_TRACE(std::string(real) + ", " + grid + " grid, " + c.name);
                const RunResult never = run_opencl(c, options_for(real, grid, "0"));
                for (const char* interval : {"1", "3"}) {
                    SCOPED_TRACE(std::string("sort_interval ") + interval);
                    const RunResult reordered = run_opencl(c, options_for(real, grid, interval));
                    EXPECT_EQ(reordered.final_state.x, never.final_state.x);
                    EXPECT_EQ(reordered.final_state.y, never.final_state.y);
                    EXPECT_EQ(reordered.final_state.vx, never.final_state.vx);
                    EXPECT_EQ(reordered.final_state.vy, never.final_state.vy);
                    EXPECT_EQ(reordered.stats.contacts, never.stats.contacts);
                    EXPECT_GT(reordered.stats.phase_seconds.count(phase::reorder), 0u) << "no reorder ran";
                }
            }
}

// A value as the backend stores it: rounded to float in a float build.
double as_stored(double value, const std::string& real) { return real == "float" ? double(float(value)) : value; }

// Three radii and five masses, in random order: a disk that came back under another disk's index
// would show a wrong radius or mass.
TEST(OpenclReorder, ReadStateKeepsEachDisksIdentity) {
    OpenclCase c = random_listing_gas();
    c.name = "polydisperse, unequal masses";
    ParticleState<double>& s = c.initial;
    for (std::size_t i = 0; i < s.size(); ++i) {
        s.radius[i] = i % 3 == 0 ? 0.25 : i % 3 == 1 ? 0.3 : 0.4;  // random_gas placed them 0.8 apart
        s.mass[i] = 0.5 * double(1 + i % 5);
        s.inv_mass[i] = 1 / s.mass[i];
    }
    for (const char* real : {"double", "float"})
        for (const char* grid : {"host", "device"}) {
            SCOPED_TRACE(std::string(real) + ", " + grid + " grid");
            const RunResult r = run_opencl(c, options_for(real, grid, "1"));
            const ParticleState<double>& out = r.final_state;
            ASSERT_EQ(out.size(), s.size());
            for (std::size_t i = 0; i < s.size(); ++i) {
                ASSERT_EQ(out.radius[i], as_stored(s.radius[i], real)) << "disk " << i;
                ASSERT_EQ(out.mass[i], as_stored(s.mass[i], real)) << "disk " << i;
                ASSERT_EQ(out.inv_mass[i], as_stored(s.inv_mass[i], real)) << "disk " << i;
            }
        }
}

TEST(OpenclReorder, SortIntervalZeroNeverReorders) {
    const OpenclCase c = random_listing_gas();
    for (const char* grid : {"host", "device"}) {
        SCOPED_TRACE(grid);
        const RunResult never = run_opencl(c, options_for("float", grid, "0"));
        EXPECT_EQ(never.stats.phase_seconds.count(phase::reorder), 0u);
        EXPECT_EQ(never.stats.steps, steps);
    }
}

// (grid = "group", the default for small scenes, never reorders: test_opencl_group.cpp.)
BackendOptions host_grid() {
    BackendOptions options;
    options.extra["grid"] = "host";
    return options;
}

TEST(OpenclReorder, DefaultReordersAtEveryGridBuild) {
    auto solver = backend("opencl").create(host_grid());
    const OpenclCase c = random_listing_gas();
    solver->load(c.scene, c.initial);
    EXPECT_EQ(solver->provenance().at("sort_interval"), "1");
}

TEST(OpenclReorder, SceneTableSetsSortIntervalAndOptionsWin) {
    OpenclCase c = random_listing_gas();
    c.scene.backend_options["opencl"]["sort_interval"] = "0";
    auto from_scene = backend("opencl").create(host_grid());
    from_scene->load(c.scene, c.initial);
    EXPECT_EQ(from_scene->provenance().at("sort_interval"), "0");
    BackendOptions explicit_option = host_grid();
    explicit_option.extra["sort_interval"] = "4";
    auto from_options = backend("opencl").create(explicit_option);
    from_options->load(c.scene, c.initial);
    EXPECT_EQ(from_options->provenance().at("sort_interval"), "4");
}

}  // namespace
}  // namespace collide::test
