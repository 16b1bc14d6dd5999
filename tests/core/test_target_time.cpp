// The one target-time check (core/numerics/target_time.h): what it refuses, with which words, and that
// every backend's advance_to applies it before doing any work.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/backend_registry.h"
#include "core/numerics/target_time.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

TEST(TargetTime, RefusesWhatNoRunCouldReach) {
    EXPECT_EQ(target_time_problem(nan, 0, 1e-3, false), "target time t = nan is not a finite number");
    EXPECT_EQ(target_time_problem(inf, 0, 1e-3, true), "target time t = inf is not a finite number");
    EXPECT_EQ(target_time_problem(-inf, 0, 1e-3, true), "target time t = -inf is not a finite number");
    EXPECT_EQ(target_time_problem(1e300, 0, 1e-3, true),
              "target time t = 1e+300: expected at most 1000000000000 steps of dt = 0.001 (this is 1e+303 steps)");
    EXPECT_EQ(target_time_problem(0.01, 0.05, 1e-3, false),
              "target time t = 0.01 is in the past: the simulation is at t = 0.05 and never goes backwards");
}

TEST(TargetTime, AcceptsTheCapItselfAndTheCurrentStep) {
    EXPECT_EQ(target_time_problem(1e9, 0, 1e-3, true), "");  // exactly max_steps steps
    EXPECT_NE(target_time_problem(1.0000001e9, 0, 1e-3, true), "");
    // Stepped backends sit at k dt; a t rounding to step k is "now", not the past.
    EXPECT_EQ(target_time_problem(0.2999999, 3 * 0.1, 0.1, true), "");
    EXPECT_NE(target_time_problem(0.2999999, 3 * 0.1, 0.1, false), "");
}

TEST(TargetTime, TheSceneReaderUsesTheSameCapWords) {
    EXPECT_EQ(steps_cap_problem(1e300, 1e-3), "at most 1000000000000 steps of dt = 0.001 (this is 1e+303 steps)");
    EXPECT_EQ(steps_cap_problem(1.0, 1e-3), "");
}

// Every backend compiled in refuses the same targets with the same words and is left as it was.
TEST(TargetTime, EveryBackendRefusesBeforeAnyWork) {
    Scene scene = test::box_scene(10, 10);
    scene.run.dt = 1e-3;
    const auto initial = test::make_state({{2, 5, 1, 0, 0.5, 1}, {8, 5, -1, 0, 0.5, 1}});
    for (const BackendInfo& backend : all_backends()) {
        std::unique_ptr<Solver> solver;
        try {
            solver = backend.create({});
            solver->load(scene, initial);
        } catch (const std::exception& e) {  // e.g. no OpenCL device on this machine
            std::cout << backend.name << " left out: " << e.what() << "\n";
            continue;
        }
        solver->advance_to(0.5);
        for (double t : {nan, inf, 1e300, 0.1}) {
            try {
                solver->advance_to(t);
                ADD_FAILURE() << backend.name << " accepted t = " << t;
            } catch (const std::invalid_argument& e) {
                EXPECT_EQ(std::string(e.what()), backend.name + ": " + target_time_problem(t, 0.5, 1e-3, true))
                    << backend.name;
            }
            EXPECT_DOUBLE_EQ(solver->time(), 0.5) << backend.name;
        }
    }
}

}  // namespace
}  // namespace collide
