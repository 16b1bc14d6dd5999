// The pure collision-time functions of the event-driven solver against hand-solved cases.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/collision_time.h"

namespace collide::event_time {
namespace {

TEST(PairCollisionTime, HeadOnGapClosedAtRelativeSpeed) {
    // Centres 4 apart, contact distance 1, closing at speed 2: the gap of 3 closes at t = 1.5.
    EXPECT_DOUBLE_EQ(pair_collision_time(-4, 0, 2, 0, 1), 1.5);
}

TEST(PairCollisionTime, GlancingImpactParameter) {
    // d = (-3, 0.5), u = (1, 0), sigma = 1: contact when (3 - t)^2 + 0.25 = 1, t = 3 - sqrt(3/4).
    EXPECT_NEAR(pair_collision_time(-3, 0.5, 1, 0, 1), 3 - std::sqrt(0.75), 1e-15);
}

TEST(PairCollisionTime, MissesWhenImpactParameterExceedsContactDistance) {
    EXPECT_EQ(pair_collision_time(-3, 1.0001, 1, 0, 1), never);
}

TEST(PairCollisionTime, SeparatingPairNeverCollides) {
    EXPECT_EQ(pair_collision_time(4, 0, 2, 0, 1), never);
    EXPECT_EQ(pair_collision_time(-4, 0, 0, 0, 1), never);
}

TEST(PairCollisionTime, TouchingOrRoundOffOverlappingApproachingPairCollidesNow) {
    EXPECT_EQ(pair_collision_time(-1, 0, 1, 0, 1), 0.0);
    EXPECT_EQ(pair_collision_time(-1 + 1e-15, 0, 1, 0, 1), 0.0);
    // ... but a touching pair that separates does not.
    EXPECT_EQ(pair_collision_time(-1, 0, -1, 0, 1), never);
}

TEST(PairCollisionTime, StableForNearlyTouchingPair) {
    // Gap 2^-40 (about 1e-12, exact in binary) closed at speed 1: the naive root
    // (-b - sqrt(D)) / u^2 subtracts two numbers near 1 and keeps only ~4 digits of the gap.
    const double gap = std::ldexp(1.0, -40);
    EXPECT_NEAR(pair_collision_time(-(1 + gap), 0, 1, 0, 1), gap, 1e-12 * gap);
}

TEST(CrossingTime, LinearMotion) {
    EXPECT_DOUBLE_EQ(upward_crossing_time(3, 2, 0), 1.5);
    EXPECT_EQ(upward_crossing_time(3, -2, 0), never);
    EXPECT_DOUBLE_EQ(downward_crossing_time(-3, -2, 0), 1.5);
    EXPECT_EQ(downward_crossing_time(-3, 2, 0), never);
}

TEST(CrossingTime, ThrownUpUnderGravity) {
    // q(t) = 4 t - 5 t^2 (a = -10): reaches 0.6 upwards at t = 0.2, comes back down through it
    // at t = 0.6, never reaches 1 (apex 0.8), and falls back through 0 at t = 0.8.
    EXPECT_NEAR(upward_crossing_time(0.6, 4, -10), 0.2, 1e-15);
    EXPECT_NEAR(downward_crossing_time(0.6, 4, -10), 0.6, 1e-15);
    EXPECT_EQ(upward_crossing_time(1.0, 4, -10), never);
    EXPECT_NEAR(downward_crossing_time(0.0, 4, -10), 0.8, 1e-15);
}

TEST(CrossingTime, FallingFromRest) {
    // q(t) = -g t^2 / 2 with g = 9.81: reaches -2 after sqrt(4 / 9.81).
    EXPECT_NEAR(downward_crossing_time(-2, 0, -9.81), std::sqrt(4 / 9.81), 1e-15);
    // Pulled upwards while moving down: turns around and crosses a level above on the way up.
    EXPECT_NEAR(upward_crossing_time(1, -1, 2), (std::sqrt(5.0) + 1) / 2, 1e-15);
}

TEST(CrossingTime, LevelJustPassedByRoundOffIsNow) {
    EXPECT_EQ(upward_crossing_time(-1e-16, 1, 0), 0.0);
    EXPECT_EQ(downward_crossing_time(1e-16, -1, -9.81), 0.0);
}

}  // namespace
}  // namespace collide::event_time
