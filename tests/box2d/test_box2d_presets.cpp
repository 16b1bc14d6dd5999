// The two Box2D presets: `shipped` must be Box2D 2.4 exactly as it comes, checked against the
// objects Box2D itself initialises (never against copied numbers), and the difference that
// matters most to hard disks, the restitution threshold, must show on a slow collision.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include "box2d/box2d_solver.h"
#include "core/scene/option_reader.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

constexpr double kFloat = 1e-5;

Scene preset_scene(const std::string& preset) {
    Scene scene = test::box_scene(10, 4);
    scene.name = "preset_case";
    scene.run.dt = 1e-3;
    scene.backend_options["box2d"] = {{"preset", preset}};
    return scene;
}

// Two equal disks (radius 0.5) meeting head-on at relative speed 2 v, run for 3 s.
ParticleState<double> head_on(const Scene& scene, double v) {
    Box2dSolver solver;
    solver.load(scene, test::make_state({{4, 2, v, 0, 0.5, 1}, {6, 2, -v, 0, 0.5, 1}}));
    solver.advance_to(3.0);
    ParticleState<double> s;
    solver.read_state(s);
    return s;
}

TEST(Box2dPresets, ShippedIsWhatBox2dInitialises) {
    Box2dSolver solver;
    solver.load(preset_scene("shipped"), test::make_state({{5, 2, 1, 0, 0.5, 1}}));
    const b2World fresh_world(b2Vec2(0.0f, 0.0f));
    const b2BodyDef fresh_body;
    const b2FixtureDef fresh_fixture;
    const b2World& world = *solver.world();
    const b2Body& body = *solver.body(0);
    EXPECT_EQ(world.GetAllowSleeping(), fresh_world.GetAllowSleeping());
    EXPECT_EQ(world.GetWarmStarting(), fresh_world.GetWarmStarting());
    EXPECT_EQ(world.GetContinuousPhysics(), fresh_world.GetContinuousPhysics());
    EXPECT_EQ(body.IsSleepingAllowed(), fresh_body.allowSleep);
    EXPECT_EQ(body.IsFixedRotation(), fresh_body.fixedRotation);
    EXPECT_EQ(body.IsBullet(), fresh_body.bullet);
    EXPECT_EQ(body.GetAngularDamping(), fresh_body.angularDamping);
    EXPECT_EQ(body.GetGravityScale(), fresh_body.gravityScale);
    EXPECT_EQ(body.GetFixtureList()->GetRestitutionThreshold(), fresh_fixture.restitutionThreshold);
    // Scene units are metres, 1:1: a disk of radius 0.5 is a 0.5 m circle.
    EXPECT_EQ(solver.units().scale, 1.0);
    EXPECT_EQ(body.GetFixtureList()->GetShape()->m_radius, 0.5f);
    // Box2D 2.4 has no default iteration counts; its manual recommends 8 and 3.
    EXPECT_EQ(solver.options().velocity_iterations, 8);
    EXPECT_EQ(solver.options().position_iterations, 3);
}

TEST(Box2dPresets, TunedDiffersFromShippedWhereTheDocsSay) {
    Box2dSolver solver;
    solver.load(preset_scene("tuned"), test::make_state({{5, 2, 1, 0, 0.25, 1}}));
    EXPECT_FALSE(solver.world()->GetAllowSleeping());
    EXPECT_FALSE(solver.body(0)->IsSleepingAllowed());
    EXPECT_TRUE(solver.body(0)->IsFixedRotation());
    EXPECT_EQ(solver.body(0)->GetFixtureList()->GetRestitutionThreshold(), 0.0f);
    EXPECT_EQ(solver.units().scale, 2.0);  // mean radius 0.25 becomes 0.5 m
    EXPECT_EQ(solver.options().preset, "tuned");
}

TEST(Box2dPresets, KeysOnTopOfAPresetReplaceOneValueEach) {
    Scene scene = preset_scene("shipped");
    scene.backend_options["box2d"]["restitution_threshold"] = "0";
    scene.backend_options["box2d"]["velocity_iterations"] = "20";
    Box2dSolver solver;
    solver.load(scene, test::make_state({{5, 2, 1, 0, 0.5, 1}}));
    EXPECT_EQ(solver.body(0)->GetFixtureList()->GetRestitutionThreshold(), 0.0f);
    EXPECT_EQ(solver.options().velocity_iterations, 20);
    EXPECT_TRUE(solver.world()->GetAllowSleeping());  // the rest is still shipped
    EXPECT_EQ(solver.options().preset, "shipped");
}

TEST(Box2dPresets, UnknownPresetIsNamedWithTheValidOnes) {
    Box2dSolver solver;
    try {
        solver.load(preset_scene("default"), test::make_state({{5, 2, 1, 0, 0.5, 1}}));
        FAIL() << "an unknown preset must stop the load";
    } catch (const BackendOptionError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("preset"), std::string::npos) << message;
        EXPECT_NE(message.find("'default'"), std::string::npos) << message;
        EXPECT_NE(message.find("shipped"), std::string::npos) << message;
    }
}

TEST(Box2dPresets, SlowHeadOnCollisionBouncesWhenTunedAndStopsWhenShipped) {
    // Relative speed 0.5 m/s in Box2D's units (scale 1 in both presets for radius 0.5), below
    // Box2D's restitution threshold of 1 m/s: shipped solves for zero normal relative velocity,
    // a perfectly inelastic collision, so equal masses stop dead; tuned exchanges velocities.
    const auto tuned = head_on(preset_scene("tuned"), 0.25);
    EXPECT_NEAR(tuned.vx[0], -0.25, kFloat);
    EXPECT_NEAR(tuned.vx[1], 0.25, kFloat);
    const auto shipped = head_on(preset_scene("shipped"), 0.25);
    EXPECT_NEAR(shipped.vx[0], 0.0, kFloat);
    EXPECT_NEAR(shipped.vx[1], 0.0, kFloat);
    // Above the threshold (relative speed 2 m/s) shipped bounces too.
    const auto fast = head_on(preset_scene("shipped"), 1.0);
    EXPECT_NEAR(fast.vx[0], -1.0, kFloat);
}

TEST(Box2dPresets, ProvenanceRecordsThePresetAndEverySetting) {
    Box2dSolver solver;
    solver.load(preset_scene("shipped"), test::make_state({{5, 2, 1, 0, 0.5, 1}}));
    const auto p = solver.provenance();
    EXPECT_EQ(p.at("box2d_preset"), "shipped");
    EXPECT_EQ(p.at("box2d_sleeping"), "true");
    EXPECT_EQ(p.at("box2d_fixed_rotation"), "false");
    EXPECT_EQ(std::stod(p.at("box2d_restitution_threshold_box2d_units")), 1.0);
    for (const char* key : {"box2d_warm_starting", "box2d_continuous", "box2d_bullet", "box2d_length_scale",
                            "box2d_velocity_iterations", "box2d_position_iterations", "box2d_substeps"})
        EXPECT_TRUE(p.count(key)) << key;
}

}  // namespace
}  // namespace collide
