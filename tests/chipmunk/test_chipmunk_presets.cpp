// The two Chipmunk presets: `shipped` must be Chipmunk 7 as it comes, checked against a cpSpace
// Chipmunk itself initialises (never against copied numbers); `tuned` differs where
// docs/engines.md says, and keys on top of a preset replace one value each.
#include <gtest/gtest.h>

#include <chipmunk/chipmunk.h>

#include <cmath>
#include <memory>

#include "chipmunk/chipmunk_solver.h"
#include "core/scene/option_reader.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

Scene preset_scene(const std::string& preset) {
    Scene scene = test::box_scene(10, 4);
    scene.name = "preset_case";
    scene.run.dt = 1e-3;
    scene.backend_options["chipmunk"] = {{"preset", preset}};
    return scene;
}

TEST(ChipmunkPresets, ShippedIsWhatChipmunkInitialises) {
    ChipmunkSolver solver;
    solver.load(preset_scene("shipped"), test::make_state({{5, 2, 1, 0, 0.5, 2}}));
    const std::unique_ptr<cpSpace, decltype(&cpSpaceFree)> fresh(cpSpaceNew(), &cpSpaceFree);
    const cpSpace* space = solver.space();
    EXPECT_EQ(cpSpaceGetCollisionSlop(space), cpSpaceGetCollisionSlop(fresh.get()));
    EXPECT_EQ(cpSpaceGetCollisionBias(space), cpSpaceGetCollisionBias(fresh.get()));
    EXPECT_EQ(cpSpaceGetIterations(space), cpSpaceGetIterations(fresh.get()));
    EXPECT_EQ(cpSpaceGetSleepTimeThreshold(space), cpSpaceGetSleepTimeThreshold(fresh.get()));
    // A spinning solid disk: the moment of inertia of a circle, m r^2 / 2.
    EXPECT_DOUBLE_EQ(cpBodyGetMoment(solver.body(0)), cpMomentForCircle(2, 0, 0.5, cpvzero));
    EXPECT_EQ(solver.options().combine, "product");
}

TEST(ChipmunkPresets, TunedDiffersFromShippedWhereTheDocsSay) {
    ChipmunkSolver solver;
    solver.load(preset_scene("tuned"), test::make_state({{5, 2, 1, 0, 0.5, 1}}));
    EXPECT_EQ(cpSpaceGetCollisionSlop(solver.space()), 0.0);
    EXPECT_TRUE(std::isinf(cpBodyGetMoment(solver.body(0))));  // no spin
    EXPECT_EQ(solver.options().combine, "scene");
    EXPECT_EQ(solver.options().preset, "tuned");
    // What tuned keeps of Chipmunk's own.
    const std::unique_ptr<cpSpace, decltype(&cpSpaceFree)> fresh(cpSpaceNew(), &cpSpaceFree);
    EXPECT_EQ(cpSpaceGetCollisionBias(solver.space()), cpSpaceGetCollisionBias(fresh.get()));
    EXPECT_EQ(cpSpaceGetIterations(solver.space()), cpSpaceGetIterations(fresh.get()));
}

TEST(ChipmunkPresets, KeysOnTopOfAPresetReplaceOneValueEach) {
    Scene scene = preset_scene("shipped");
    scene.backend_options["chipmunk"]["collision_slop"] = "0.001";
    scene.backend_options["chipmunk"]["iterations"] = "20";
    ChipmunkSolver solver;
    solver.load(scene, test::make_state({{5, 2, 1, 0, 0.5, 1}}));
    EXPECT_EQ(cpSpaceGetCollisionSlop(solver.space()), 0.001);
    EXPECT_EQ(cpSpaceGetIterations(solver.space()), 20);
    EXPECT_EQ(solver.options().combine, "product");  // the rest is still shipped
}

TEST(ChipmunkPresets, BadValuesAreNamedWithWhatWasExpected) {
    for (const auto& [key, value, expected] : {std::tuple{"preset", "default", "shipped"},
                                               std::tuple{"combine", "max", "product"},
                                               std::tuple{"collision_bias", "2", "[0, 1]"},
                                               std::tuple{"slop", "0", "collision_slop"}}) {
        Scene scene = preset_scene("tuned");
        scene.backend_options["chipmunk"][key] = value;
        ChipmunkSolver solver;
        try {
            solver.load(scene, test::make_state({{5, 2, 1, 0, 0.5, 1}}));
            FAIL() << key << " = " << value << " must stop the load";
        } catch (const BackendOptionError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(key), std::string::npos) << message;
            EXPECT_NE(message.find(expected), std::string::npos) << message;
        }
    }
}

TEST(ChipmunkPresets, ProvenanceRecordsTheLibraryVersionAndEverySetting) {
    ChipmunkSolver solver;
    solver.load(preset_scene("shipped"), test::make_state({{5, 2, 1, 0, 0.5, 1}}));
    const auto p = solver.provenance();
    EXPECT_EQ(p.at("chipmunk_version"), cpVersionString);
    EXPECT_EQ(p.at("chipmunk_preset"), "shipped");
    EXPECT_EQ(p.at("chipmunk_combine"), "product");
    EXPECT_EQ(p.at("chipmunk_fixed_rotation"), "false");
    for (const char* key : {"chipmunk_collision_slop", "chipmunk_collision_bias", "chipmunk_iterations", "chipmunk_substeps"})
        EXPECT_TRUE(p.count(key)) << key;
}

}  // namespace
}  // namespace collide
