// The parts of the MPI hand-out that need no MPI: when a run counts as launched by MPI, and
// the order in which cases are handed out (longest expected first, measured speeds on resume).
#include <gtest/gtest.h>

#include <cstdlib>

#include "validation/run/case_dispatch.h"

namespace collide::validation {
namespace {

Scene gas(std::int64_t disks, double duration, double dt) {
    Scene s;
    s.run.duration = duration;
    s.run.dt = dt;
    ParticleGenerator g;
    g.kind = "gas";
    g.count = disks;
    s.generators.push_back(g);
    return s;
}

CaseSpec spec(const std::string& id, const std::string& scene, const std::string& backend) {
    CaseSpec c;
    c.id = id;
    c.scene = scene;
    c.backend = backend;
    return c;
}

TEST(CaseDispatch, PlainRunIsNotAnMpiRunAndGetsNoDispatch) {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"}) ::unsetenv(name);
    EXPECT_FALSE(launched_by_mpi_launcher());
    EXPECT_EQ(start_case_dispatch(2, false), nullptr);  // and MPI is never initialised
    EXPECT_EQ(serial_execution(3).at("jobs_per_rank"), "3");
    EXPECT_EQ(serial_execution(3).at("ranks"), "1");
}

TEST(CaseDispatch, CostIsDisksTimesStepsWithoutMeasurements) {
    const std::map<std::string, CaseResult> none;
    EXPECT_DOUBLE_EQ(estimated_cost(spec("a", "gas", "step"), gas(1000, 2.0, 1e-3), none), 1000.0 * 2000);
    CaseSpec refused = spec("b", "gas", "box2d");
    refused.left_out = "no periodic walls";
    EXPECT_EQ(estimated_cost(refused, gas(1000, 2.0, 1e-3), none), 0.0);
}

TEST(CaseDispatch, MeasuredSpeedOfTheSameSceneAndBackendTurnsCostIntoSeconds) {
    CaseResult done;
    done.spec = spec("gas__box2d__seed1", "gas", "box2d");
    done.disks = 1000, done.duration = 2.0, done.dt = 1e-3, done.wall_seconds = 3.0, done.warmup_seconds = 1.0;
    const std::map<std::string, CaseResult> finished = {{done.spec.id, done}};
    // 4 s for 2e6 disk-steps: 2e-6 s per disk-step, so half the steps cost 2 s.
    EXPECT_NEAR(estimated_cost(spec("gas__box2d__seed2", "gas", "box2d"), gas(1000, 1.0, 1e-3), finished), 2.0, 1e-12);
}

TEST(CaseDispatch, LongestFirstSkipsFinishedCasesAndKeepsPlanOrderAmongEquals) {
    const std::vector<CaseSpec> specs = {spec("short", "a", "step"), spec("long", "a", "step"),
                                         spec("done", "a", "step"), spec("short2", "a", "step")};
    std::map<std::string, CaseResult> finished;
    finished["done"] = CaseResult{};
    const std::map<std::string, double> cost = {{"short", 1}, {"long", 5}, {"done", 9}, {"short2", 1}};
    const auto order = longest_first(specs, finished, [&](const CaseSpec& s) { return cost.at(s.id); });
    EXPECT_EQ(order, (std::vector<int>{1, 0, 3}));
}

}  // namespace
}  // namespace collide::validation
