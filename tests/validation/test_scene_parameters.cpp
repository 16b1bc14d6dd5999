// Scene-parameter sweeps: a `set` path changes exactly the key it names, the changed scene
// goes through every scene rule again, a bad path is a clear error, and the plan crosses the
// values with the dt sweep while the reference runs once per value.
#include <gtest/gtest.h>

#include <optional>
#include <toml++/toml.h>

#include <set>

#include "core/scene/scene_loader.h"
#include "test_backends.h"
#include "validation/plan/case_plan.h"
#include "validation/plan/scene_parameters.h"

namespace collide::validation {
namespace {

const char* kScene = R"(
description = "two disks and a small gas"
[world]
box = [0.0, 0.0, 10.0, 4.0]
[run]
duration = 1.0
output_interval = 0.1
dt = 1e-3
[[particles]]
kind = "list"
disks = [ { x = 4.0, y = 2.0, vx = 1.0, vy = 0.0, radius = 0.5, mass = 1.0 },
          { x = 6.0, y = 2.0, vx = 0.0, vy = 0.0, radius = 0.5, mass = 1.0 } ]
[[particles]]
kind = "gas"
count = 3
radius = 0.1
mass = 1.0
velocity = { maxwell = 1.0 }
)";

Scene base() {
    Scene s = parse_scene(kScene, "scenes/pair.toml");
    s.source_path = "scenes/pair.toml";
    return s;
}

std::string error_of(const std::string& path, double value) {
    try {
        scene_with_parameters(base(), {{path, value}});
    } catch (const SuiteError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no SuiteError for " << path << " = " << value;
    return "";
}

TEST(SceneParameters, AppliesTheValueToExactlyTheNamedKey) {
    const Scene s = scene_with_parameters(base(), {{"particles.0.disks.1.mass", 1e9}});
    const auto state = generate_initial_state(s);
    EXPECT_EQ(state.mass[1], 1e9);  // the swept disk
    EXPECT_EQ(state.mass[0], 1.0);  // its partner is untouched
    EXPECT_EQ(s.name, "pair");
    // Provenance carries the changed text: read back, it holds the new value (spelt as toml++
    // writes it, the shortest text that reads back to the same double).
    const toml::table text = toml::parse(s.source_text);
    EXPECT_EQ(text["particles"][0]["disks"][1]["mass"].value<double>(), std::optional<double>(1e9)) << s.source_text;
    // An integer key takes an integral value and stays an integer.
    EXPECT_EQ(generate_initial_state(scene_with_parameters(base(), {{"particles.1.count", 5}})).size(), 7u);
}

TEST(SceneParameters, UnknownPathsAndWrongTypesAreClearErrors) {
    auto msg = error_of("particles.0.disks.7.mass", 2);
    EXPECT_NE(msg.find("scenes/pair.toml"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no element 7 in 'particles.0.disks' (it has 2)"), std::string::npos) << msg;
    msg = error_of("particles.0.disks.1.weight", 2);
    EXPECT_NE(msg.find("no key 'weight' in 'particles.0.disks.1'"), std::string::npos) << msg;
    msg = error_of("physics.gravity", 2);
    EXPECT_NE(msg.find("no key 'physics'"), std::string::npos) << msg;
    msg = error_of("particles.1.count", 2.5);
    EXPECT_NE(msg.find("integer"), std::string::npos) << msg;
    msg = error_of("particles.0.kind", 1);
    EXPECT_NE(msg.find("string"), std::string::npos) << msg;
}

TEST(SceneParameters, EveryValueStillObeysTheSceneRules) {
    // A negative mass is rejected by parse_scene, with the swept path and value in front.
    const auto msg = error_of("particles.0.disks.1.mass", -1);
    EXPECT_NE(msg.find("particles.0.disks.1.mass = -1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("mass"), std::string::npos) << msg;
}

TEST(SceneParameters, SuiteFilesReadQuotedPathsAndHintAtUnquotedOnes) {
    const std::string dir = test::fresh_output_dir("parameter_suite");
    // An existing file named by its absolute path (not __FILE__, which a compiler cache may
    // have made relative): the parser only checks that the scene path exists.
    const std::string existing = std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/head_on_equal.toml";
    const auto suite = parse_suite(
        "scene_dir = \".\"\n[[scene]]\npath = \"" + existing +
            "\"\nset = { \"particles.0.disks.1.mass\" = [1.0, 1e9] }\n",
        "suites/p.toml", dir);
    ASSERT_EQ(suite.scenes[0].set.size(), 1u);
    EXPECT_EQ(suite.scenes[0].set[0].path, "particles.0.disks.1.mass");
    EXPECT_EQ(suite.scenes[0].set[0].values, (std::vector<double>{1.0, 1e9}));
    try {
        parse_suite("[[scene]]\npath = \"" + existing + "\"\nset = { particles.mass = [1.0] }\n",
                    "suites/p.toml", dir);
        ADD_FAILURE() << "an unquoted dotted path must be an error";
    } catch (const SuiteError& e) {
        EXPECT_NE(std::string(e.what()).find("quote"), std::string::npos) << e.what();
    }
}

TEST(SceneParameters, PlanCrossesValuesWithDtAndRunsTheReferenceOncePerValue) {
    auto suite = test::test_suite(base(), {"all"});
    suite.seeds = {1};
    suite.scenes[0].dt = {0.01, 0.001};
    suite.scenes[0].set = {{"particles.0.disks.1.mass", {1.0, 1e3, 1e6}}};
    const std::vector<BackendInfo> backends = {test::test_backend("event", test::Fault::none),
                                               test::test_backend("step", test::Fault::none)};
    const auto cases = plan_cases(suite, {base()}, select_backends(suite, backends));
    EXPECT_EQ(cases.size(), 3u + 3u * 2u);  // event: one per value; step: value x dt
    std::set<std::string> ids;
    for (const auto& c : cases) ids.insert(c.id);
    EXPECT_EQ(ids.size(), cases.size());
    EXPECT_TRUE(ids.count("pair__step__particles.0.disks.1.mass=1e+06__dt0.001__seed1")) << *ids.begin();
    EXPECT_TRUE(ids.count("pair__event__particles.0.disks.1.mass=1000__seed1"));
}

}  // namespace
}  // namespace collide::validation
