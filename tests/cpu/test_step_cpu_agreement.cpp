// `cpu` (float) and `step` (double) implement the same rules, so over a short horizon their
// states differ only by float rounding, amplified by the collisions in between.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "cpu/cpu_solver.h"
#include "reference/step_solver.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

// The tolerance, derived (not tuned). Notation: L the box size, n the number of steps,
// eps = FLT_EPSILON (the float rounding step relative to 1), R = 2r the contact distance,
// u = 2 sqrt(2) the largest relative speed of two disks with velocities in [-1, 1]^2.
//  * Rounding: converting the state to float and every step's x += v dt each round a
//    position by at most eps |x| <= eps L, so without collisions the float run is within
//    delta = (n + 1) eps L of the double run.
//  * Growth: a collision turns a position error delta into a velocity error of at most
//    (2 u / R) delta (the normal direction tilts by delta / R) which, over the remaining
//    time T, adds (2 u T / R) delta of position error. The horizon is chosen so that
//    2 u T / R <= 1: each collision at most doubles the error. In this gas (area fraction
//    0.25) a disk has at most two collisions in T (checked below through the contact
//    count), so the growth factor is at most 2^2 = 4.
//  * Positions then agree within 4 delta and velocities within 4 (2 u / R) delta.
// Left out of the bound: a contact that float detects one step after double (overlap at
// the detection step below the rounding error, probability ~1e-3 per contact); it would
// appear here as an error of order (1 + e) u dt, and be a failure worth investigating.
// Both contact searches of `cpu`: the pair list (skin 0.5, the default) and the cell path (0).
TEST(StepCpuAgreement, GasStatesAgreeToFloatRoundingOverAShortHorizon) {
    for (const char* skin : {"0.5", "0"})
    for (StepOrder order : {StepOrder::collide_first, StepOrder::integrate_first}) {
        SCOPED_TRACE(std::string("skin ") + skin);
        Scene scene = test::box_scene(20, 20);
        scene.physics.restitution = 0.8;
        scene.physics.friction = 0.1;
        scene.physics.gravity_y = -1.0;
        scene.run.order = order;
        scene.run.substeps = 2;
        const double radius = 0.4, contact = 2 * radius, u_max = 2 * std::sqrt(2.0);
        scene.run.dt = 1e-3;
        const double horizon = contact / (2 * u_max);  // 2 u T / R = 1
        const auto steps = std::int64_t(horizon / scene.run.dt);
        const double t = double(steps) * scene.run.dt;
        const auto initial = test::random_gas(scene, 200, radius, 5);  // area fraction 200 pi 0.4^2 / 400 = 0.25

        StepSolver step;
        cpu::CpuSolver cpu({2, "", "", {{"skin", skin}}});
        ParticleState<double> a, b;
        for (Solver* s : {static_cast<Solver*>(&step), static_cast<Solver*>(&cpu)}) {
            s->load(scene, initial);
            s->advance_to(t);
        }
        step.read_state(a);
        cpu.read_state(b);
        ASSERT_GT(step.stats().contacts, 20) << "the horizon should contain collisions";
        // Each contact involves two disks: fewer contacts than disks means under two per disk on average.
        ASSERT_LT(step.stats().contacts, std::int64_t(initial.size())) << "at most a few collisions per disk";
        EXPECT_EQ(cpu.stats().contacts, step.stats().contacts);

        const double delta = double(steps + 1) * FLT_EPSILON * 20.0;
        const double position_tol = 4 * delta, velocity_tol = 4 * (2 * u_max / contact) * delta;
        double worst_x = 0, worst_v = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            worst_x = std::max({worst_x, std::abs(a.x[i] - b.x[i]), std::abs(a.y[i] - b.y[i])});
            worst_v = std::max({worst_v, std::abs(a.vx[i] - b.vx[i]), std::abs(a.vy[i] - b.vy[i])});
        }
        EXPECT_LT(worst_x, position_tol) << to_string(order);
        EXPECT_LT(worst_v, velocity_tol) << to_string(order);
        // And the comparison is not vacuous: float really differs from double.
        EXPECT_GT(worst_x, 0.0);
    }
}

}  // namespace
}  // namespace collide
