// Which checks apply to which scene: one test per rule of "Leave out what a scene does not need".
#include <gtest/gtest.h>

#include "validation/judge/applicability.h"

namespace collide::validation {
namespace {

SceneFeatures periodic_elastic() {
    SceneFeatures f;
    f.reflecting_walls = false;
    return f;
}

TEST(Applicability, PeriodicElasticGasChecksEverything) {
    const auto f = periodic_elastic();
    EXPECT_FALSE(momentum_left_out(f));
    EXPECT_EQ(energy_check(f).kind, EnergyKind::kinetic);
    EXPECT_TRUE(wall_penetration_left_out(f));
    EXPECT_FALSE(pressure_left_out(f));
}

TEST(Applicability, MomentumNeedsNoWallsGravityDampingOrStones) {
    auto f = periodic_elastic();
    f.reflecting_walls = true;
    EXPECT_NE(momentum_left_out(f)->find("walls"), std::string::npos);
    f = periodic_elastic();
    f.gravity = true;
    EXPECT_NE(momentum_left_out(f)->find("gravity"), std::string::npos);
    f = periodic_elastic();
    f.damping = true;
    EXPECT_NE(momentum_left_out(f)->find("damping"), std::string::npos);
    f = periodic_elastic();
    f.stones = true;
    EXPECT_NE(momentum_left_out(f)->find("stones"), std::string::npos);
    f = periodic_elastic();
    f.restitution = 0.5;  // inelastic pair collisions still conserve momentum
    EXPECT_FALSE(momentum_left_out(f));
}

TEST(Applicability, KineticEnergyNeedsElasticFrictionlessUndampedScenes) {
    auto f = periodic_elastic();
    f.restitution = 0.9;
    EXPECT_EQ(energy_check(f).kind, EnergyKind::none);
    EXPECT_NE(energy_check(f).reason.find("restitution"), std::string::npos);
    f = periodic_elastic();
    f.reflecting_walls = true;
    f.wall_restitution = 0.8;
    EXPECT_EQ(energy_check(f).kind, EnergyKind::none);
    EXPECT_NE(energy_check(f).reason.find("wall restitution"), std::string::npos);
    f = periodic_elastic();
    f.wall_restitution = 0.8;  // no walls in a periodic box: wall restitution does not matter
    EXPECT_EQ(energy_check(f).kind, EnergyKind::kinetic);
    f = periodic_elastic();
    f.friction = true;
    EXPECT_NE(energy_check(f).reason.find("friction"), std::string::npos);
    f = periodic_elastic();
    f.damping = true;
    EXPECT_NE(energy_check(f).reason.find("damping"), std::string::npos);
    f = periodic_elastic();
    f.stones = true;  // resting stones reflect elastically
    EXPECT_EQ(energy_check(f).kind, EnergyKind::kinetic);
    f.moving_stones = true;
    EXPECT_EQ(energy_check(f).kind, EnergyKind::none);
}

TEST(Applicability, GravityChecksTotalEnergyInstead) {
    auto f = periodic_elastic();
    f.gravity = true;
    EXPECT_EQ(energy_check(f).kind, EnergyKind::total);
    f.restitution = 0.5;
    EXPECT_EQ(energy_check(f).kind, EnergyKind::none);
}

TEST(Applicability, PressureNeedsOneDiameter) {
    auto f = periodic_elastic();
    f.uniform_radius = false;
    EXPECT_TRUE(pressure_left_out(f));
}

TEST(Applicability, OverlappingPairsOnlyWhereTheLimitAllowsTenPairs) {
    // Two disks overlap in at most 0.5 pairs per disk: a limit of 0.5 (or box2d's 1.0) passes
    // them overlapping at every step, so the check is left out with its reason.
    const auto two = overlapping_pairs_too_few(2, 0.5);
    ASSERT_TRUE(two);
    EXPECT_NE(two->find("2 disks overlap in at most 0.5 pairs per disk"), std::string::npos) << *two;
    EXPECT_TRUE(overlapping_pairs_too_few(3, 1.0)) << "3 disks: at most 1 pair per disk";
    // Where the limit allows fewer than ten pairs, one pair fails it: a count of single pairs.
    const auto single = overlapping_pairs_too_few(2, 0.25);
    ASSERT_TRUE(single);
    EXPECT_NE(single->find("a count of single pairs"), std::string::npos) << *single;
    EXPECT_TRUE(overlapping_pairs_too_few(99, 0.1));
    // Where the limit allows ten pairs or more, the check is judged and can fail.
    EXPECT_FALSE(overlapping_pairs_too_few(100, 0.1));
    EXPECT_FALSE(overlapping_pairs_too_few(10, 1.0));
    EXPECT_FALSE(overlapping_pairs_too_few(1000, 0.05));
}

TEST(Applicability, OverlapBeyondStepJudgesExactlyWhereOverlappingPairsCannot) {
    // The replacement: judged where the count is left out, left out (with its reason) where
    // the count judges.
    for (const auto& [disks, limit] : {std::pair<std::size_t, double>{2, 0.5}, {3, 1.0}, {2, 0.25}, {1000, 0.05}}) {
        const bool count_left_out = overlapping_pairs_too_few(disks, limit).has_value();
        const auto why = overlap_beyond_step_left_out(disks, limit);
        EXPECT_NE(count_left_out, why.has_value()) << disks << " disks, limit " << limit;
        if (why) {
            EXPECT_NE(why->find("overlapping_pairs judges"), std::string::npos) << *why;
        }
    }
    EXPECT_NE(overlapping_pairs_too_few(2, 0.5)->find("overlap_beyond_step judges in its place"), std::string::npos);
}

TEST(Applicability, FeaturesAreReadFromSceneAndState) {
    Scene scene;
    scene.world.boundary = Boundary::periodic;
    scene.physics.gravity_y = -1;
    ParticleState<double> s;
    s.x = {1, 2}; s.y = {1, 2}; s.vx = {0, 1}; s.vy = {0, 0};
    s.radius = {0.1, 0.2}; s.mass = {1, 1}; s.inv_mass = {1, 0};
    const auto f = scene_features(scene, s);
    EXPECT_FALSE(f.reflecting_walls);
    EXPECT_TRUE(f.gravity);
    EXPECT_TRUE(f.stones);
    EXPECT_TRUE(f.moving_stones);
    EXPECT_FALSE(f.uniform_radius);
}

}  // namespace
}  // namespace collide::validation
