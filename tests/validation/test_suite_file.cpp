// Suite files: what a valid file gives, and that every mistake names the file and the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "test_backends.h"
#include "validation/plan/case_plan.h"

namespace collide::validation {
namespace {

// A scene directory with one (empty) scene file, so paths resolve.
std::string scene_dir() {
    const auto dir = std::filesystem::path(test::fresh_output_dir("suite_scenes"));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "gas.toml") << "# placeholder\n";
    return dir.string();
}

std::string expect_error(const std::string& text) {
    try {
        parse_suite(text, "suites/bad.toml", scene_dir());
    } catch (const SuiteError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no SuiteError for:\n" << text;
    return "";
}

TEST(SuiteFile, ParsesSweepsSeedsAndTolerances) {
    const auto suite = parse_suite(R"(
name = "demo"
scene_dir = "."
backends = ["step"]
seeds = [3, 4]
[tolerances.default]
energy_drift = 0.5
[tolerances.step]
max_overlap = 0.25
[[scene]]
name = "gas"
compare = "statistics"
dt = [0.01, 0.005]
substeps = [1, 2]
)", "suites/demo.toml", scene_dir());
    EXPECT_EQ(suite.name, "demo");
    ASSERT_EQ(suite.scenes.size(), 1u);
    EXPECT_EQ(suite.scenes[0].comparison, Comparison::statistics);
    EXPECT_EQ(suite.scenes[0].dt.size(), 2u);
    EXPECT_EQ(suite.seeds, (std::vector<std::uint64_t>{3, 4}));
    const auto t = suite.tolerances.for_backend(find_backend("step"));
    EXPECT_EQ(t.energy_drift, 0.5);
    EXPECT_EQ(t.max_overlap, 0.25);
}

TEST(SuiteFile, PlanIsScenesTimesBackendsTimesSweepTimesSeedsWithTheReferenceRunOnce) {
    auto suite = test::test_suite(test::two_disk_scene(), {"all"});
    suite.scenes[0].dt = {0.01, 0.005, 0.0025};
    suite.scenes[0].substeps = {1, 2};
    const std::vector<BackendInfo> backends = {test::test_backend("event", test::Fault::none),
                                               test::test_backend("step", test::Fault::none)};
    const auto cases = plan_cases(suite, {test::two_disk_scene()}, select_backends(suite, backends));
    // event: 2 seeds; step: 3 dt x 2 substeps x 2 seeds.
    EXPECT_EQ(cases.size(), 2u + 12u);
    std::set<std::string> ids;
    for (const auto& c : cases) ids.insert(c.id);
    EXPECT_EQ(ids.size(), cases.size()) << "case ids must be unique";
}

// Plans the suite on event and step and returns the SuiteError's message ("" when it plans).
std::string plan_error(const Suite& suite, const std::vector<Scene>& scenes) {
    const std::vector<BackendInfo> backends = {test::test_backend("event", test::Fault::none),
                                               test::test_backend("step", test::Fault::none)};
    try {
        plan_cases(suite, scenes, select_backends(suite, backends));
    } catch (const SuiteError& e) {
        return e.what();
    }
    return "";
}

// Two cases with one id wrote one record, and summary.json listed it twice: one result lost.
TEST(SuiteFile, CasesThatWouldShareAnIdAreRefusedBeforeAnyRuns) {
    auto suite = test::test_suite(test::two_disk_scene(), {"all"});
    suite.source_path = "suites/twice.toml";
    suite.scenes[0].line = 7;
    suite.scenes.push_back(suite.scenes[0]);  // a repeated [[scene]] (or two files with one stem)
    suite.scenes[1].line = 12;
    std::string msg = plan_error(suite, {test::two_disk_scene(), test::two_disk_scene()});
    EXPECT_NE(msg.find("planned twice"), std::string::npos) << msg;
    EXPECT_NE(msg.find("suites/twice.toml:12"), std::string::npos) << msg;
    EXPECT_NE(msg.find("suites/twice.toml:7"), std::string::npos) << msg;
    EXPECT_NE(msg.find("`name`"), std::string::npos) << msg;

    suite.scenes.pop_back();
    suite.scenes[0].seeds = {3, 3};  // a repeated seed
    msg = plan_error(suite, {test::two_disk_scene()});
    EXPECT_NE(msg.find("seed3"), std::string::npos) << msg;

    suite.scenes[0].seeds = {3};
    suite.scenes[0].dt = {0.01, 0.01};  // a repeated dt
    EXPECT_NE(plan_error(suite, {test::two_disk_scene()}).find("planned twice"), std::string::npos);
}

// "%g" printed dt = 0.0010000001 and 0.001 alike; the id must read back as the case's dt.
TEST(SuiteFile, DtAndParameterValuesInIdsRoundTrip) {
    auto suite = test::test_suite(test::two_disk_scene(), {"step"});
    suite.scenes[0].dt = {0.001, 0.0010000001, 1.0 / 3.0};
    suite.scenes[0].set = {SceneParameter{"world.restitution", {0.9, 0.90000001}}};
    const std::vector<BackendInfo> backends = {test::test_backend("step", test::Fault::none)};
    const auto cases = plan_cases(suite, {test::two_disk_scene()}, select_backends(suite, backends));
    std::set<std::string> ids;
    for (const auto& c : cases) {
        ids.insert(c.id);
        const auto at = c.id.find("__dt");
        ASSERT_NE(at, std::string::npos) << c.id;
        EXPECT_EQ(std::stod(c.id.substr(at + 4)), *c.dt) << c.id;
    }
    EXPECT_EQ(ids.size(), cases.size()) << "3 dt x 2 restitutions x seeds, each its own id";
}

TEST(SuiteFile, IterationsSweepOnlyMultipliesBackendsThatHaveIterations) {
    auto suite = test::test_suite(test::two_disk_scene(), {"all"});
    suite.scenes[0].iterations = {8, 16, 32};
    BackendInfo iterative = test::test_backend("iterative", test::Fault::none);
    iterative.sweeps_iterations = true;
    const std::vector<BackendInfo> backends = {test::test_backend("event", test::Fault::none),
                                               test::test_backend("step", test::Fault::none), iterative};
    const auto cases = plan_cases(suite, {test::two_disk_scene()}, select_backends(suite, backends));
    std::map<std::string, int> per_backend;
    for (const auto& c : cases) {
        ++per_backend[c.backend];
        EXPECT_EQ(c.iterations.has_value(), c.backend == "iterative") << c.id;
    }
    // 2 seeds each; only the iterative backend is run once per sweep value.
    EXPECT_EQ(per_backend["event"], 2);
    EXPECT_EQ(per_backend["step"], 2);
    EXPECT_EQ(per_backend["iterative"], 6);
}

TEST(SuiteFile, ErrorsNameTheFileTheKeyAndWhatWasExpected) {
    auto msg = expect_error("scene_dir = \".\"\n[[scene]]\nname = \"gas\"\ndt = [0.01, -1]\n");
    EXPECT_NE(msg.find("suites/bad.toml:4"), std::string::npos) << msg;
    EXPECT_NE(msg.find("dt"), std::string::npos) << msg;
    EXPECT_NE(msg.find("positive"), std::string::npos) << msg;

    msg = expect_error("scene_dir = \".\"\n[[scene]]\nname = \"nonexistent\"\n");
    EXPECT_NE(msg.find("nonexistent.toml does not exist"), std::string::npos) << msg;

    msg = expect_error("scene_dir = \".\"\n[[scene]]\nname = \"gas\"\ncompare = \"sideways\"\n");
    EXPECT_NE(msg.find("compare"), std::string::npos) << msg;

    msg = expect_error("scene_dir = \".\"\ntypo_key = 1\n[[scene]]\nname = \"gas\"\n");
    EXPECT_NE(msg.find("typo_key"), std::string::npos) << msg;

    msg = expect_error("scene_dir = \".\"\n[tolerances.step]\nenergy_drif = 1\n[[scene]]\nname = \"gas\"\n");
    EXPECT_NE(msg.find("tolerances.step.energy_drif"), std::string::npos) << msg;

    msg = expect_error("name = [1\n");
    EXPECT_NE(msg.find("not valid TOML"), std::string::npos) << msg;

    msg = expect_error("name = \"x\"\n");
    EXPECT_NE(msg.find("[[scene]]"), std::string::npos) << msg;
}

}  // namespace
}  // namespace collide::validation
