// The [backend.box2d] table: defaults, values, and clear errors for unknown keys and bad values.
#include <gtest/gtest.h>

#include <stdexcept>

#include "box2d/box2d_options.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

Scene scene_with(std::map<std::string, std::string> table) {
    Scene scene = test::box_scene(10, 10);
    scene.name = "options_case";
    scene.backend_options["box2d"] = std::move(table);
    return scene;
}

// Runs parse_box2d_options and returns the error message ("" if it did not throw).
std::string error_of(std::map<std::string, std::string> table) {
    try {
        parse_box2d_options(scene_with(std::move(table)));
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(Box2dOptions, DefaultsAreBox2dRecommendedIterationsAndNoThreshold) {
    const Box2dOptions o = parse_box2d_options(test::box_scene(10, 10));
    EXPECT_EQ(o.restitution_threshold, 0.0);
    EXPECT_EQ(o.velocity_iterations, 8);
    EXPECT_EQ(o.position_iterations, 3);
    EXPECT_FALSE(o.substeps.has_value());
    EXPECT_FALSE(o.bullet);
    EXPECT_FALSE(o.length_scale.has_value());
    EXPECT_EQ(o.preset, "tuned");
    EXPECT_FALSE(o.sleeping);
    EXPECT_TRUE(o.fixed_rotation);
}

TEST(Box2dOptions, ReadsEveryKey) {
    const Box2dOptions o = parse_box2d_options(scene_with({{"restitution_threshold", "1.5"},
                                                           {"velocity_iterations", "20"},
                                                           {"position_iterations", "6"},
                                                           {"substeps", "4"},
                                                           {"bullet", "true"},
                                                           {"length_scale", "0.25"},
                                                           {"sleeping", "true"},
                                                           {"warm_starting", "false"},
                                                           {"continuous", "false"},
                                                           {"fixed_rotation", "false"}}));
    EXPECT_EQ(o.restitution_threshold, 1.5);
    EXPECT_EQ(o.velocity_iterations, 20);
    EXPECT_EQ(o.position_iterations, 6);
    EXPECT_EQ(o.substeps, 4);
    EXPECT_TRUE(o.bullet);
    EXPECT_EQ(o.length_scale, 0.25);
    EXPECT_TRUE(o.sleeping);
    EXPECT_FALSE(o.warm_starting);
    EXPECT_FALSE(o.continuous);
    EXPECT_FALSE(o.fixed_rotation);
}

TEST(Box2dOptions, UnknownKeyIsNamedWithTheValidOnes) {
    const std::string message = error_of({{"velocity_iteration", "8"}});
    EXPECT_NE(message.find("options_case"), std::string::npos) << message;
    EXPECT_NE(message.find("velocity_iteration"), std::string::npos) << message;
    EXPECT_NE(message.find("unknown key"), std::string::npos) << message;
    EXPECT_NE(message.find("velocity_iterations"), std::string::npos) << message;
}

TEST(Box2dOptions, BadValuesSayWhatWasExpected) {
    EXPECT_NE(error_of({{"velocity_iterations", "0"}}).find("whole number >= 1"), std::string::npos);
    EXPECT_NE(error_of({{"position_iterations", "2.5"}}).find("whole number >= 1"), std::string::npos);
    EXPECT_NE(error_of({{"substeps", "4x"}}).find("'4x'"), std::string::npos);
    EXPECT_NE(error_of({{"bullet", "yes"}}).find("true or false"), std::string::npos);
    EXPECT_NE(error_of({{"length_scale", "-1"}}).find("scale > 0"), std::string::npos);
    EXPECT_NE(error_of({{"restitution_threshold", "-0.1"}}).find("speed >= 0"), std::string::npos);
    EXPECT_NE(error_of({{"restitution_threshold", "fast"}}).find("a number"), std::string::npos);
    EXPECT_NE(error_of({{"sleeping", "1"}}).find("true or false"), std::string::npos);
    EXPECT_NE(error_of({{"preset", "default"}}).find("\"tuned\" or \"shipped\""), std::string::npos);
}

}  // namespace
}  // namespace collide
