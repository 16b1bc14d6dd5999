// SceneFeatures (core/scene/scene_features.h) is worked out once and every consumer reads it: the
// cpu loop instantiation, the OpenCL -D flags, the event solvers' refusals and validation's
// applicability. Each consumer is checked here against the features, feature by feature.
#include <gtest/gtest.h>

#include <string>

#include "core/scene/scene_features.h"
#include "cpu/feature_set.h"
#include "opencl/step_params.h"
#include "reference/event/event_solver.h"
#include "reference/plain_event_solver.h"
#include "tests/support/test_scenes.h"
#include "validation/judge/applicability.h"

namespace collide {
namespace {

// Two disks of radius 0.1 and 0.2; the second a stone moving at vx = 1.
ParticleState<double> disk_and_moving_stone() {
    return test::make_state({{1, 1, 0, 0, 0.1, 1}, {2, 2, 1, 0, 0.2, 1, true}});
}

TEST(SceneFeatures, FromTheSceneAndItsState) {
    Scene scene = test::box_scene(4, 5, Boundary::periodic);
    scene.physics.gravity_y = -1;
    scene.physics.restitution = 0.9;
    const SceneFeatures f = scene_features(scene, disk_and_moving_stone());
    EXPECT_TRUE(f.periodic());
    EXPECT_TRUE(f.gravity);
    EXPECT_FALSE(f.damping);
    EXPECT_FALSE(f.friction);
    EXPECT_EQ(f.restitution, 0.9);
    EXPECT_TRUE(f.stones);
    EXPECT_TRUE(f.moving_stones);
    EXPECT_FALSE(f.uniform_radius);
    EXPECT_DOUBLE_EQ(f.area_fraction, 3.141592653589793 * (0.01 + 0.04) / 20);

    const SceneFeatures plain = scene_features(test::box_scene(4, 5), test::make_state({{1, 1, 0, 0, 0.1, 1}, {2, 2, 0, 0, 0.1, 1}}));
    EXPECT_TRUE(plain.reflecting_walls);
    EXPECT_FALSE(plain.gravity || plain.stones || plain.moving_stones);
    EXPECT_TRUE(plain.uniform_radius);
    EXPECT_FALSE(uniform_radius(ParticleState<double>{})) << "no disks: no one radius";
}

TEST(SceneFeatures, StonesDeclaredInTheSceneFile) {
    Scene scene = test::box_scene(4, 4);
    EXPECT_FALSE(scene_features(scene).stones);
    ParticleGenerator g;
    g.stone = true;
    scene.generators.push_back(g);
    EXPECT_TRUE(scene_features(scene).stones);
}

TEST(SceneFeatures, CpuInstantiationFollowsTheFeatures) {
    SceneFeatures f;
    f.friction = true;
    f.stones = true;
    f.uniform_radius = false;
    const cpu::FeatureSet set = cpu::FeatureSet::of(f);
    EXPECT_TRUE(set.friction && set.stones && set.periodic);
    EXPECT_FALSE(set.gravity || set.damping || set.uniform_radius);
}

TEST(SceneFeatures, OpenclFlagsFollowTheFeatures) {
    Scene scene = test::box_scene(4, 5);
    scene.physics.friction = 0.5;
    const std::string flags = opencl::feature_flags(scene, disk_and_moving_stone(), false);
    EXPECT_NE(flags.find("COLLIDE_FRICTION"), std::string::npos) << flags;
    EXPECT_NE(flags.find("COLLIDE_STONES"), std::string::npos) << flags;
    EXPECT_EQ(flags.find("COLLIDE_UNIFORM_RADIUS"), std::string::npos) << flags;
    EXPECT_EQ(flags.find("COLLIDE_PERIODIC"), std::string::npos) << flags;
    EXPECT_EQ(flags.find("COLLIDE_GRAVITY"), std::string::npos) << flags;
}

TEST(SceneFeatures, EventSolversRefuseGravityWithStones) {
    Scene scene = test::box_scene(4, 4);
    scene.physics.gravity_y = -1;
    EXPECT_FALSE(EventSolver::supports(scene));
    ParticleGenerator g;
    g.stone = true;
    scene.generators.push_back(g);
    EXPECT_TRUE(EventSolver::supports(scene));
    EXPECT_TRUE(PlainEventSolver::supports(scene));
}

TEST(SceneFeatures, PressureNeedsOneRadius) {
    SceneFeatures f;
    EXPECT_FALSE(validation::pressure_left_out(f));
    f.uniform_radius = false;
    EXPECT_TRUE(validation::pressure_left_out(f));
}

}  // namespace
}  // namespace collide
