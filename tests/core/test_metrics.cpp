// Metrics on small states whose values are computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/numerics/compensated_sum.h"
#include "core/metrics.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

TEST(Metrics, MomentumAndEnergyByHand) {
    Scene scene = test::box_scene(10, 10);
    const auto s = test::make_state({{1, 1, 2, 0, 0.5, 3}, {5, 5, -1, 4, 0.5, 2}, {8, 8, 7, 7, 0.5, 1, true}});
    const Metrics m = compute_metrics(scene, s, 0.5);
    EXPECT_EQ(m.time, 0.5);
    EXPECT_DOUBLE_EQ(m.momentum_x, 3 * 2 + 2 * -1);  // the stone is left out
    EXPECT_DOUBLE_EQ(m.momentum_y, 2 * 4);
    EXPECT_DOUBLE_EQ(m.kinetic_energy, 0.5 * 3 * 4 + 0.5 * 2 * 17);
    EXPECT_EQ(m.potential_energy, 0.0);
    EXPECT_EQ(m.overlapping_pairs, 0);
    EXPECT_EQ(m.nonfinite, 0);
}

TEST(Metrics, KineticEnergyIsTheSumOfEachMobileDisks) {
    EXPECT_EQ(disk_kinetic_energy(2, 3, 4), 25.0);  // m |v|^2 / 2 = 2 * 25 / 2
    const Scene scene = test::box_scene(10, 10);
    // The second disk is a stone: it moves, but carries no kinetic energy of the budget.
    const auto s = test::make_state({{1, 1, 3, 4, 0.5, 2}, {5, 5, 1, 0, 0.5, 7, true}, {8, 8, -1, 2, 0.5, 3}});
    EXPECT_EQ(compute_disk_metrics(scene, s, 0).kinetic_energy, disk_kinetic_energy(2, 3, 4) + disk_kinetic_energy(3, -1, 2));
}

TEST(Metrics, GravitationalPotentialEnergy) {
    Scene scene = test::box_scene(10, 10);
    scene.physics.gravity_y = -9.81;
    const auto s = test::make_state({{1, 2, 0, 0, 0.5, 3}});
    EXPECT_DOUBLE_EQ(compute_metrics(scene, s, 0).potential_energy, 3 * 9.81 * 2);
}

TEST(Metrics, OverlapDepthsRelativeToContactDistance) {
    Scene scene = test::box_scene(10, 10);
    // Pair A: radii 1 and 1 at distance 1.5 -> depth 0.5/2 = 0.25.
    // Pair B: radii 0.5 and 0.5 at distance 0.9 -> depth 0.1/1 = 0.1.
    const auto s = test::make_state({{2, 2, 0, 0, 1, 1}, {3.5, 2, 0, 0, 1, 1},
                                     {7, 7, 0, 0, 0.5, 1}, {7, 7.9, 0, 0, 0.5, 1}});
    const Metrics m = compute_metrics(scene, s, 0);
    EXPECT_EQ(m.overlapping_pairs, 2);
    EXPECT_DOUBLE_EQ(m.max_overlap, 0.25);
    EXPECT_NEAR(m.mean_overlap, 0.175, 1e-15);
}

TEST(Metrics, OverlapBeyondOneStepOfTheApproach) {
    Scene scene = test::box_scene(10, 10);
    scene.run.dt = 0.02;
    scene.run.substeps = 2;  // h = 0.01
    // Pair A: contact 1, depth 0.1, relative speed 4: one step presses 0.04 in, 0.06 is beyond.
    // Pair B: contact 1, depth 0.02, relative speed 3: within one step (0.03), nothing beyond.
    const auto s = test::make_state({{2, 2, 2, 0, 0.5, 1}, {2.9, 2, -2, 0, 0.5, 1},
                                     {7, 7, 0, 3, 0.5, 1}, {7, 7.98, 0, 0, 0.5, 1}});
    const Metrics m = compute_metrics(scene, s, 0);
    EXPECT_EQ(m.overlapping_pairs, 2);
    EXPECT_NEAR(m.max_overlap_beyond_step, 0.06, 1e-12);
    // Resting in contact (no relative motion): the whole depth is beyond one step.
    const auto resting = test::make_state({{2, 2, 1, 1, 0.5, 1}, {2.95, 2, 1, 1, 0.5, 1}});
    EXPECT_NEAR(compute_metrics(scene, resting, 0).max_overlap_beyond_step, 0.05, 1e-12);
    EXPECT_EQ(compute_metrics(scene, test::make_state({{2, 2, 0, 0, 0.5, 1}}), 0).max_overlap_beyond_step, 0.0);
}

TEST(Metrics, PeriodicOverlapAcrossTheBoundary) {
    Scene scene = test::box_scene(10, 10, Boundary::periodic);
    const auto s = test::make_state({{0.2, 5, 0, 0, 0.5, 1}, {9.6, 5, 0, 0, 0.5, 1}});
    const Metrics m = compute_metrics(scene, s, 0);
    EXPECT_EQ(m.overlapping_pairs, 1);
    EXPECT_NEAR(m.max_overlap, 0.4, 1e-12);
    EXPECT_EQ(m.max_wall_penetration, 0.0);  // no walls in a periodic box
}

TEST(Metrics, WallPenetrationRelativeToRadius) {
    Scene scene = test::box_scene(10, 10);
    const auto s = test::make_state({{0.3, 5, 0, 0, 0.5, 1}, {5, 9.9, 0, 0, 0.2, 1}});
    // Disk 0 reaches 0.2 past x = 0 (0.4 of its radius); disk 1 0.1 past y = 10 (0.5).
    EXPECT_NEAR(compute_metrics(scene, s, 0).max_wall_penetration, 0.5, 1e-12);
}

TEST(Metrics, NonFiniteDisksAreCountedNotSummed) {
    Scene scene = test::box_scene(10, 10);
    auto s = test::make_state({{1, 1, 1, 0, 0.5, 1}, {5, 5, 0, 0, 0.5, 1}});
    s.vx[1] = std::numeric_limits<double>::quiet_NaN();
    const Metrics m = compute_metrics(scene, s, 0);
    EXPECT_EQ(m.nonfinite, 1);
    EXPECT_DOUBLE_EQ(m.kinetic_energy, 0.5);
}

TEST(CompensatedSum, RecoversWhatNaiveSummationLoses) {
    // 1 + 1e-16 * 10^6: naive double summation returns exactly 1.
    CompensatedSum sum;
    double naive = 1.0;
    sum.add(1.0);
    for (int k = 0; k < 1000000; ++k) { sum.add(1e-16); naive += 1e-16; }
    EXPECT_EQ(naive, 1.0);
    EXPECT_NEAR(sum.value(), 1.0 + 1e-10, 1e-22);
}

}  // namespace
}  // namespace collide
