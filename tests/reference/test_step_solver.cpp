// The `step` backend on cases with exact answers that belong to its rules (Euler steps, gravity
// in either order); head-on, wall and periodic cases are conformance bodies
// (tests/conformance/test_conformance.cpp), run on every backend.
#include <gtest/gtest.h>

#include <cmath>

#include "core/metrics.h"
#include "core/numerics/state_hash.h"
#include "reference/step_solver.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

TEST(StepSolver, FreeFlightIsExactEuler) {
    Scene scene = test::box_scene(100, 100);
    scene.run.dt = 0.25;
    StepSolver solver;
    solver.load(scene, test::make_state({{10, 10, 2, -1, 0.5, 1}}));
    solver.advance_to(4.0);
    ParticleState<double> s;
    solver.read_state(s);
    EXPECT_DOUBLE_EQ(s.x[0], 18.0);
    EXPECT_DOUBLE_EQ(s.y[0], 6.0);
    EXPECT_EQ(solver.stats().steps, 16);
}

TEST(StepSolver, GravityFollowsExplicitEulerInCollideFirst) {
    Scene scene = test::box_scene(100, 100);
    scene.physics.gravity_y = -1.0;
    scene.run.dt = 0.5;
    StepSolver solver;
    solver.load(scene, test::make_state({{50, 50, 0, 0, 0.5, 1}}));
    solver.advance_to(2.0);  // 4 steps: y = 50 - dt^2 (0 + 1 + 2 + 3) = 48.5
    ParticleState<double> s;
    solver.read_state(s);
    EXPECT_DOUBLE_EQ(s.y[0], 48.5);
    EXPECT_DOUBLE_EQ(s.vy[0], -2.0);
}

TEST(StepSolver, GravityFollowsSemiImplicitEulerInIntegrateFirst) {
    Scene scene = test::box_scene(100, 100);
    scene.physics.gravity_y = -1.0;
    scene.run.dt = 1.0;
    scene.run.substeps = 2;
    scene.run.order = StepOrder::integrate_first;
    StepSolver solver;
    solver.load(scene, test::make_state({{50, 50, 0, 0, 0.5, 1}}));
    solver.advance_to(1.0);  // h = 0.5: y = 50 - h^2 (1 + 2) = 49.25
    ParticleState<double> s;
    solver.read_state(s);
    EXPECT_DOUBLE_EQ(s.y[0], 49.25);
    EXPECT_DOUBLE_EQ(s.vy[0], -1.0);
}

TEST(StepSolver, RerunsAreBitwiseIdentical) {
    Scene scene = test::box_scene(20, 20);
    scene.run.dt = 5e-3;
    const auto initial = test::random_gas(scene, 200, 0.4, 11);
    std::uint64_t hashes[2];
    for (auto& h : hashes) {
        StepSolver solver;
        solver.load(scene, initial);
        solver.advance_to(1.0);
        ParticleState<double> s;
        solver.read_state(s);
        h = state_hash(s);
    }
    EXPECT_EQ(hashes[0], hashes[1]);
}

}  // namespace
}  // namespace collide
