// Test bodies that every backend must pass (see conformance.h). Each names its case
// (conformance_cases.cpp) and checks the exact answer; a body that checks exact event times
// runs on the exact solvers only (skip_unless_exact), the others on every backend that
// supports the scene.
#include "conformance.h"

#include <cmath>

#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

TEST_P(Conformance, HeadOnEqualMassesExchangeVelocities) {
    const ConformanceCase& c = conformance_case("head_on");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const RunResult r = run(c);
    // They meet at t = 1.5 and swap velocities; at t = 2 each moves with the other's speed.
    EXPECT_NEAR(r.final_state.vx[0], -1.0, tolerance());
    EXPECT_NEAR(r.final_state.vx[1], 1.0, tolerance());
    EXPECT_NEAR(r.final_state.vy[0], 0.0, tolerance());
    EXPECT_NEAR(r.series.back().kinetic_energy, 1.0, tolerance());
    EXPECT_NEAR(r.series.back().momentum_x, 0.0, tolerance());
    if (!is_exact(GetParam())) return;
    // Contact at x = 4.5 and 5.5; then each flies 0.5 with the other's velocity.
    EXPECT_NEAR(r.final_state.x[0], 4.0, 1e-12);
    EXPECT_NEAR(r.final_state.x[1], 6.0, 1e-12);
    EXPECT_EQ(r.stats.contacts, 1);
}

TEST_P(Conformance, HeadOnMassRatioTenFollowsElasticFormula) {
    const ConformanceCase& c = conformance_case("mass_ratio_10");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const RunResult r = run(c);
    // v1' = (m1 - m2)/(m1 + m2) u1 = -9/11, v2' = 2 m1/(m1 + m2) u1 = 2/11.
    EXPECT_NEAR(r.final_state.vx[0], -9.0 / 11.0, tolerance());
    EXPECT_NEAR(r.final_state.vx[1], 2.0 / 11.0, tolerance());
    if (!is_exact(GetParam())) return;
    EXPECT_NEAR(r.final_state.x[0], 6.0 - 9.0 / 11.0 * 1.5, 1e-12);  // contact at t = 0.5, x1 = 6
    EXPECT_NEAR(r.final_state.x[1], 7.0 + 2.0 / 11.0 * 1.5, 1e-12);
}

TEST_P(Conformance, GlancingCollisionUnequalMasses) {
    const ConformanceCase& c = conformance_case("glancing");
    if (skip_unless_exact(c.scene)) GTEST_SKIP();
    const RunResult r = run(c);
    const auto& s = r.final_state;
    // Contact distance 1 is reached at t_c = 3 - sqrt(3/4) with normal n = (-sqrt(3/4), -1/2).
    // v_i' = v_i - 2 m_j/(m_i + m_j) (u.n) n = (0, -sqrt(3/4) 2/3),
    // v_j' =       2 m_i/(m_i + m_j) (u.n) n = (1/2, sqrt(3/4) / 3).
    const double k = std::sqrt(0.75), tc = 3 - k, t = 4;
    EXPECT_NEAR(s.vx[0], 0.0, 1e-12);
    EXPECT_NEAR(s.vy[0], -2 * k / 3, 1e-12);
    EXPECT_NEAR(s.vx[1], 0.5, 1e-12);
    EXPECT_NEAR(s.vy[1], k / 3, 1e-12);
    EXPECT_NEAR(s.x[0], 5 + tc, 1e-12);
    EXPECT_NEAR(s.y[0], 5 - 2 * k / 3 * (t - tc), 1e-12);
    EXPECT_NEAR(s.x[1], 8 + 0.5 * (t - tc), 1e-12);
    EXPECT_NEAR(s.y[1], 5.5 + k / 3 * (t - tc), 1e-12);
}

TEST_P(Conformance, MomentumAndEnergyOfPeriodicElasticGas) {
    const ConformanceCase& c = conformance_case("periodic_gas");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const RunResult r = run(c);
    const Metrics &a = r.series.front(), &b = r.series.back();
    // Momentum: every pair impulse is equal and opposite, so only rounding changes it.
    double momentum_scale = 0;
    for (std::size_t i = 0; i < c.initial.size(); ++i) momentum_scale += std::hypot(c.initial.vx[i], c.initial.vy[i]);
    EXPECT_NEAR(b.momentum_x, a.momentum_x, tolerance() * momentum_scale);
    EXPECT_NEAR(b.momentum_y, a.momentum_y, tolerance() * momentum_scale);
    EXPECT_GT(r.stats.contacts, 0);
    EXPECT_EQ(b.nonfinite, 0);
    // Kinetic energy: conserved by every elastic collision; the exact solvers have no other error.
    if (is_exact(GetParam())) {
        EXPECT_NEAR(b.kinetic_energy, a.kinetic_energy, 1e-12 * a.kinetic_energy);
    }
}

TEST_P(Conformance, StoneNeverMoves) {
    const ConformanceCase& c = conformance_case("stone");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const RunResult r = run(c);
    EXPECT_EQ(r.final_state.x[0], 5.0);
    EXPECT_EQ(r.final_state.y[0], 5.0);
    EXPECT_EQ(r.final_state.vx[0], 0.0);
    EXPECT_LT(r.final_state.vx[1], 0.0) << "the disk should have bounced off the stone";
    EXPECT_GT(r.final_state.vy[2], 0.0);
    if (!is_exact(GetParam())) return;
    // Disk 1 touches the stone at t = 0.375 (gap 1.5 at speed 4) and reverses: at t = 1 it is
    // back at 3.5 - 4 * 0.625; disk 2 likewise from above.
    EXPECT_NEAR(r.final_state.vx[1], -4.0, 1e-12);
    EXPECT_NEAR(r.final_state.x[1], 3.5 - 2.5, 1e-12);
    EXPECT_NEAR(r.final_state.y[2], 6.5 + 2.5, 1e-12);
}

TEST_P(Conformance, StoneNeverMovesUnderGravityAndImpacts) {
    const ConformanceCase& c = conformance_case("stone_under_gravity");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const auto& s = run(c).final_state;
    EXPECT_EQ(s.x[0], 5.0);
    EXPECT_EQ(s.y[0], 3.0);
    EXPECT_EQ(s.vx[0], 0.0);
    EXPECT_EQ(s.vy[0], 0.0);
    // The falling disk has bounced: at t = 1.5 it is above the stone.
    EXPECT_GT(s.y[1], 3.0 + 1.5 - 0.05);
}

TEST_P(Conformance, WallsReflectOnAllFourSides) {
    const ConformanceCase& c = conformance_case("four_walls");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const auto& s = run(c).final_state;
    // Each disk reaches its wall at t = 4.75 and comes back with its speed reversed.
    EXPECT_NEAR(s.vx[0], -2.0, tolerance());
    EXPECT_NEAR(s.vx[1], 2.0, tolerance());
    EXPECT_NEAR(s.vy[2], 2.0, tolerance());
    EXPECT_NEAR(s.vy[3], -2.0, tolerance());
    // Disk 0 turns at x = 19.5 and is back at x = 19 at t = 5, disk 2 likewise at y = 1. The
    // stepped backends turn up to a step late or early (|v| dt per step, a few steps).
    const double position_tolerance = is_exact(GetParam()) ? 1e-12 : 3 * 2 * c.scene.run.dt;
    EXPECT_NEAR(s.x[0], 19.0, position_tolerance);
    EXPECT_NEAR(s.x[1], 1.0, position_tolerance);
    EXPECT_NEAR(s.y[2], 1.0, position_tolerance);
    EXPECT_NEAR(s.y[3], 19.0, position_tolerance);
}

TEST_P(Conformance, WallRestitutionScalesNormalVelocity) {
    const ConformanceCase& c = conformance_case("wall_restitution");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const auto& s = run(c).final_state;
    // Contact with x = 0 at t = 0.25: vx -2 -> +1, vy unchanged.
    EXPECT_NEAR(s.vx[0], 1.0, tolerance());
    EXPECT_NEAR(s.vy[0], 0.5, tolerance());
    EXPECT_GE(s.x[0], 0.5 - tolerance());
    if (is_exact(GetParam())) {
        EXPECT_NEAR(s.x[0], 0.5 + 0.75, 1e-12);
    }
}

TEST_P(Conformance, PeriodicCollisionAcrossTheBoundary) {
    const ConformanceCase& c = conformance_case("periodic_pair");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const auto& s = run(c).final_state;
    // Closing at speed 2 through the side, they touch at t = 0.2 and swap velocities.
    EXPECT_NEAR(s.vx[0], 1.0, tolerance());
    EXPECT_NEAR(s.vx[1], -1.0, tolerance());
    if (!is_exact(GetParam())) return;
    EXPECT_NEAR(s.x[0], 0.5 + 0.3, 1e-12);
    EXPECT_NEAR(s.x[1], 9.5 - 0.3, 1e-12);
}

TEST_P(Conformance, PeriodicFreeFlightWrapsAround) {
    const ConformanceCase& c = conformance_case("periodic_flight");
    if (skip_unless_supported(c.scene)) GTEST_SKIP();
    const auto& s = run(c).final_state;
    // 2000 steps of x += v dt round at each step: float backends drift by ~1e-4.
    const double position_tolerance = is_exact(GetParam()) ? 1e-12 : 2000 * 4 * tolerance();
    EXPECT_NEAR(s.x[0], 5.0, position_tolerance);  // 9 + 6 - 10
    EXPECT_NEAR(s.y[0], 4.0, position_tolerance);  // 9 + 5 - 10
}

TEST_P(Conformance, DroppedDiskBouncesOnFloorUnderGravity) {
    const ConformanceCase& c = conformance_case("gravity_drop");
    if (skip_unless_exact(c.scene)) GTEST_SKIP();
    const RunResult r = run(c);
    const double g = 9.81, t1 = std::sqrt(2 * 9.5 / g), v1 = g * t1, tau = 0.3;  // falls 9.5 to y = 0.5
    EXPECT_NEAR(r.final_state.y[0], 0.5 + v1 * tau - 0.5 * g * tau * tau, 1e-12);
    EXPECT_NEAR(r.final_state.vy[0], v1 - g * tau, 1e-12);
    EXPECT_EQ(r.stats.counters.at("events_wall"), 1);
    EXPECT_NEAR(r.stats.counters.at("wall_impulse_ymin"), 2 * 2 * v1, 1e-12);
}

TEST_P(Conformance, TotalEnergyIsKeptUnderGravity) {
    const ConformanceCase& c = conformance_case("gravity_four");
    if (skip_unless_exact(c.scene)) GTEST_SKIP();
    const RunResult r = run(c);
    // Kinetic plus potential energy, - sum m g.x: elastic collisions and walls keep it.
    const double e0 = r.series.front().total_energy();
    EXPECT_GT(r.stats.contacts, 0);
    EXPECT_GT(r.stats.counters.at("events_wall"), 0);
    EXPECT_NEAR(r.series.back().total_energy(), e0, 1e-12 * std::fabs(e0));
}

TEST_P(Conformance, NewtonsCradleSimultaneousCollisionsPassMomentumThrough) {
    const ConformanceCase& c = conformance_case("newtons_cradle");
    if (skip_unless_exact(c.scene)) GTEST_SKIP();
    const RunResult r = run(c);
    // The touching contacts are resolved one after the other at the same instant, and only the
    // last disk leaves (equal masses, e = 1).
    for (int i = 0; i < 4; ++i) EXPECT_EQ(r.final_state.vx[i], 0.0) << "disk " << i;
    EXPECT_EQ(r.final_state.vx[4], 1.0);
    EXPECT_EQ(r.final_state.x[0], 2.0);
    EXPECT_EQ(r.final_state.x[4], 7.0);
    EXPECT_EQ(r.stats.contacts, 4);
}

// The "billiard that counts digits of pi" (G. Galperin, Regular and Chaotic Dynamics 8 (2003)
// 375): a light disk between a wall and a heavy disk of mass ratio 100^k. The total number of
// collisions (disk-disk plus disk-wall) is the first k + 1 digits of pi.
TEST_P(Conformance, PiBilliardCountsDigitsOfPi) {
    ConformanceCase c = conformance_case("pi_billiard");
    if (skip_unless_exact(c.scene)) GTEST_SKIP();
    const std::int64_t expected[] = {3, 31, 314, 3141, 31415, 314159};
    for (int k = 0; k <= 5; ++k) {
        c.initial.mass[1] = std::pow(100.0, k);
        c.initial.inv_mass[1] = 1 / c.initial.mass[1];
        const RunResult r = run(c);
        const auto collisions = r.stats.contacts + std::int64_t(r.stats.counters.at("events_wall"));
        EXPECT_EQ(collisions, expected[k]) << "mass ratio 100^" << k;
    }
}

INSTANTIATE_TEST_SUITE_P(AllBackends, Conformance, ::testing::ValuesIn(backend_names()),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace collide::test
