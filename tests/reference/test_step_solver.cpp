// The `step` backend on cases with exact answers.
#include <gtest/gtest.h>

#include <cmath>

#include "core/metrics.h"
#include "core/state_hash.h"
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

TEST(StepSolver, HeadOnExchangeConservesEnergyAndMomentumToRounding) {
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    StepSolver solver;
    const auto initial = test::make_state({{3, 2, 1, 0, 0.5, 1}, {7, 2, -1, 0, 0.5, 1}});
    solver.load(scene, initial);
    solver.advance_to(2.0);
    ParticleState<double> s;
    solver.read_state(s);
    EXPECT_DOUBLE_EQ(s.vx[0], -1.0);
    EXPECT_DOUBLE_EQ(s.vx[1], 1.0);
    const Metrics a = compute_metrics(scene, initial, 0), b = compute_metrics(scene, s, 2);
    EXPECT_NEAR(b.kinetic_energy, a.kinetic_energy, 1e-12 * a.kinetic_energy);
    EXPECT_NEAR(b.momentum_x, a.momentum_x, 1e-12);
    EXPECT_EQ(solver.stats().contacts, 1);
}

TEST(StepSolver, WallBounceWithRestitution) {
    Scene scene = test::box_scene(10, 10);
    scene.physics.wall_restitution = 0.5;
    scene.run.dt = 0.01;
    StepSolver solver;
    solver.load(scene, test::make_state({{1, 5, -2, 0, 0.5, 1}}));
    solver.advance_to(1.0);
    ParticleState<double> s;
    solver.read_state(s);
    EXPECT_DOUBLE_EQ(s.vx[0], 1.0);
    EXPECT_GE(s.x[0], 0.5);
}

TEST(StepSolver, PeriodicWrapKeepsDisksInTheBox) {
    Scene scene = test::box_scene(10, 10, Boundary::periodic);
    scene.run.dt = 0.1;
    StepSolver solver;
    solver.load(scene, test::make_state({{9.9, 0.1, 1, -1, 0.5, 1}}));
    solver.advance_to(1.0);
    ParticleState<double> s;
    solver.read_state(s);
    EXPECT_NEAR(s.x[0], 0.9, 1e-12);
    EXPECT_NEAR(s.y[0], 9.1, 1e-12);
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
