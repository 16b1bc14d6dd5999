// Collision-phase replicates: shifts lie in (0, dt), every replicate is shifted, and the phases
// are spread evenly over the step (no two replicates alias).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/support/test_scenes.h"
#include "validation/compare/phase_shift.h"

namespace collide::validation {
namespace {

// A replicate at phase 0 keeps a hand-written scene's round collision time, on a step boundary
// for some dt of a sweep: the case the phases exist to avoid. The first replicate is no exception.
TEST(PhaseShift, EveryReplicateIsShiftedTheFirstIncluded) {
    for (std::uint64_t k = 1; k <= 12; ++k) EXPECT_GT(phase_shift(k, 4e-3), 0.1 * 4e-3 / 12) << "replicate " << k;
    EXPECT_NEAR(phase_shift(1, 1.0), 0.5 * (std::sqrt(5.0) - 1.0), 1e-15);
}

TEST(PhaseShift, PhasesOfSixReplicatesAreEvenlySpread) {
    for (double dt : {4e-3, 1e-3, 2.5e-4}) {
        std::vector<double> phases;
        for (std::uint64_t k = 1; k <= 6; ++k) {
            const double shift = phase_shift(k, dt);
            ASSERT_GE(shift, 0.0);
            ASSERT_LT(shift, dt);
            phases.push_back(shift / dt);
        }
        std::sort(phases.begin(), phases.end());
        // Six evenly spread phases leave gaps of 1/6; the golden-ratio sequence's largest gap
        // for 6 points is 0.236 (three-gap theorem). Aliasing would leave a gap near 1.
        double largest_gap = 1.0 - phases.back() + phases.front();
        for (std::size_t i = 1; i < phases.size(); ++i) largest_gap = std::max(largest_gap, phases[i] - phases[i - 1]);
        EXPECT_LT(largest_gap, 0.25) << "dt " << dt;
    }
}

TEST(PhaseShift, FreeFlightUnderGravityIsExact) {
    Scene scene = test::box_scene(100, 100);
    scene.physics.gravity_y = -2.0;
    auto s = test::make_state({{10, 50, 1, 3, 0.5, 1}, {20, 20, 5, 5, 1, 1, true}});
    advance_free_flight(scene, s, 0.5);
    EXPECT_DOUBLE_EQ(s.x[0], 10.5);
    EXPECT_DOUBLE_EQ(s.y[0], 50 + 1.5 - 0.25);
    EXPECT_DOUBLE_EQ(s.vy[0], 2.0);
    EXPECT_EQ(s.x[1], 20.0);  // stones do not move
}

}  // namespace
}  // namespace collide::validation
