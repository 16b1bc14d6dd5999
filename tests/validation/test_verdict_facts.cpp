// What each backend's verdict names (validation/summary/verdict_facts.h), decided in C++ against
// the suite's [verdicts] thresholds, and those thresholds read from a suite file with defaults.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/validation/test_backends.h"
#include "validation/summary/verdict_facts.h"

namespace collide::validation {
namespace {

CheckResult check(const std::string& backend, const std::string& name, double value, double tolerance,
                  CheckStatus status = CheckStatus::pass, const std::string& scene = "gas") {
    CheckResult c;
    c.subject = scene + "__" + backend;
    c.scene = scene;
    c.backend = backend;
    c.check = name;
    c.status = status;
    c.value = value;
    c.tolerance = tolerance;
    return c;
}

WorkPrecisionLine pressure_line(const std::string& backend, double sigmas, bool resolved) {
    WorkPrecisionLine line;
    line.scene = "gas";
    line.backend = backend;
    WorkPrecisionPoint point;
    StatisticalDifference d;
    d.sigmas = sigmas;
    d.resolved = resolved;
    point.pressure = d;
    line.points.push_back(point);
    return line;
}

TEST(VerdictFacts, LooseToleranceNamedFromTheThresholdOn) {
    // The others' max_overlap tolerances 0.1, 0.2, 0.3 (median 0.2); the reference's is not counted.
    const std::vector<CheckResult> checks = {
        check("event", "max_overlap", 0, 100), check("step", "max_overlap", 0, 0.1), check("cpu", "max_overlap", 0, 0.2),
        check("opencl", "max_overlap", 0, 0.3), check("loose", "max_overlap", 0, 1.0),
        check("looser", "max_overlap", 0, 1.0, CheckStatus::left_out)};  // left out: not compared
    const auto facts = verdict_facts("event", checks, {}, VerdictThresholds{}, {});
    ASSERT_TRUE(facts.at("loose").loosest_tolerance);
    EXPECT_DOUBLE_EQ(facts.at("loose").loosest_tolerance->ratio, 5.0);
    EXPECT_EQ(facts.at("loose").loosest_tolerance->check, "max_overlap");
    EXPECT_TRUE(facts.at("loose").loosest_tolerance->named);  // 5x: at the default threshold
    EXPECT_FALSE(facts.at("event").loosest_tolerance) << "the reference has no 'loose' tolerance";
    VerdictThresholds stricter;
    stricter.loose_tolerance_ratio = 5.5;
    EXPECT_FALSE(verdict_facts("event", checks, {}, stricter, {}).at("loose").loosest_tolerance->named);
}

TEST(VerdictFacts, LargestEnergyDriftNamedFromOnePercent) {
    const std::vector<CheckResult> checks = {
        check("step", "energy_drift", 0.004, 0.02, CheckStatus::pass, "a"),
        check("step", "energy_drift", 0.012, 0.02, CheckStatus::pass, "b"),
        check("step", "energy_drift", 0.5, 0.02, CheckStatus::left_out, "c"),  // not judged
        check("cpu", "energy_drift", 0.0099, 0.02)};
    const auto facts = verdict_facts("event", checks, {}, VerdictThresholds{}, {});
    ASSERT_TRUE(facts.at("step").largest_energy_drift);
    EXPECT_DOUBLE_EQ(facts.at("step").largest_energy_drift->value, 0.012);
    EXPECT_EQ(facts.at("step").largest_energy_drift->scene, "b");
    EXPECT_TRUE(facts.at("step").largest_energy_drift->named);
    EXPECT_FALSE(facts.at("cpu").largest_energy_drift->named);
}

TEST(VerdictFacts, PressureOffsetNamedWhereNotModelledOrLeftOut) {
    const std::vector<CheckResult> checks = {
        check("box2d", "pressure", 0, 0), check("step", "pressure", 0, 0),
        check("box2d[shipped]", "pressure", 0, 0, CheckStatus::left_out),
        check("stepped-left-out", "pressure", 0, 0, CheckStatus::left_out)};
    const std::vector<WorkPrecisionLine> lines = {
        pressure_line("box2d", 3.2, true), pressure_line("box2d", 9.0, false),  // unresolved: not counted
        pressure_line("step", 12.0, true), pressure_line("box2d[shipped]", 4.0, true),
        pressure_line("stepped-left-out", 4.0, true)};
    const std::map<std::string, bool> rules = {{"step", true}, {"stepped-left-out", true}};
    const auto facts = verdict_facts("event", checks, lines, VerdictThresholds{}, rules);
    EXPECT_DOUBLE_EQ(*facts.at("box2d").pressure_offset.sigmas, 3.2);
    EXPECT_TRUE(facts.at("box2d").pressure_offset.named);
    EXPECT_FALSE(facts.at("step").pressure_offset.named) << "a stepping rule's pressure is judged by its model";
    EXPECT_TRUE(facts.at("box2d[shipped]").pressure_offset.named);
    EXPECT_TRUE(facts.at("box2d[shipped]").pressure_offset.left_out);
    EXPECT_TRUE(facts.at("stepped-left-out").pressure_offset.named) << "left out: shown, never judged";
    VerdictThresholds higher;
    higher.pressure_sigmas = 5;
    EXPECT_FALSE(verdict_facts("event", checks, lines, higher, rules).at("box2d").pressure_offset.named);
}

TEST(VerdictThresholds, DefaultsAndSuiteSettings) {
    const auto dir = test::fresh_output_dir("verdict_thresholds");
    std::filesystem::create_directories(dir);
    std::ofstream(std::filesystem::path(dir) / "gas.toml") << "# placeholder\n";
    const std::string scene = "[[scene]]\nname = \"gas\"\n";
    const Suite plain = parse_suite("scene_dir = \".\"\n" + scene, "suites/plain.toml", dir);
    EXPECT_DOUBLE_EQ(plain.verdicts.loose_tolerance_ratio, 5);
    EXPECT_DOUBLE_EQ(plain.verdicts.energy_drift, 0.01);
    EXPECT_DOUBLE_EQ(plain.verdicts.pressure_sigmas, 3);
    const Suite set = parse_suite("scene_dir = \".\"\n[verdicts]\nenergy_drift = 0.05\npressure_sigmas = 4\npressure_accuracy = 0.01\n" + scene,
                                  "suites/set.toml", dir);
    EXPECT_DOUBLE_EQ(set.verdicts.energy_drift, 0.05);
    EXPECT_DOUBLE_EQ(set.verdicts.pressure_sigmas, 4);
    EXPECT_DOUBLE_EQ(set.verdicts.loose_tolerance_ratio, 5);
    EXPECT_DOUBLE_EQ(set.verdicts.pressure_accuracy, 0.01);
    EXPECT_DOUBLE_EQ(set.verdicts.trajectory_accuracy, 1e-2);  // the default
    for (const char* bad : {"[verdicts]\nenergy_drift = -1\n", "[verdicts]\nsigmas = 3\n"}) {
        try {
            parse_suite(std::string("scene_dir = \".\"\n") + bad + scene, "suites/bad.toml", dir);
            ADD_FAILURE() << "no error for " << bad;
        } catch (const SuiteError& e) {
            EXPECT_NE(std::string(e.what()).find("suites/bad.toml"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("verdicts"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace collide::validation
