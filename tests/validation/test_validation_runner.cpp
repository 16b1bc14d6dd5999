// The runner end to end with test-double backends: faults are caught, recorded and reported,
// and the suite goes on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <fstream>
#include <sstream>

#include "test_backends.h"
#include "validation/record/check_table.h"
#include "validation/suite_runner.h"

namespace collide::test {
namespace {

using validation::CheckResult;
using validation::CheckStatus;
using validation::RunStatus;

const CheckResult* find_check(const validation::SuiteOutcome& o, const std::string& backend, const std::string& check) {
    for (const auto& c : o.checks)
        if (c.backend == backend && c.check == check) return &c;
    return nullptr;
}

validation::SuiteOutcome run(const validation::Suite& suite, const std::vector<BackendInfo>& backends,
                             const std::string& dir, bool resume = false) {
    validation::RunnerOptions options;
    options.output_dir = dir;
    options.jobs = 2;
    options.resume = resume;
    return validation::run_suite(suite, backends, options);
}

TEST(ValidationRunner, CorrectBackendPassesEveryApplicableCheck) {
    const auto suite = test_suite(two_disk_scene(), {"good"});
    const auto outcome = run(suite, {test_backend("good", Fault::none)}, fresh_output_dir("good"));
    EXPECT_TRUE(outcome.passed());
    ASSERT_NE(find_check(outcome, "good", "energy_drift"), nullptr);
    EXPECT_EQ(find_check(outcome, "good", "energy_drift")->status, CheckStatus::pass);
}

TEST(ValidationRunner, BackendThatAddsEnergyFailsTheEnergyCheckWithItsMessage) {
    const auto suite = test_suite(two_disk_scene(), {"good", "pump"});
    const auto outcome =
        run(suite, {test_backend("good", Fault::none), test_backend("pump", Fault::adds_energy)}, fresh_output_dir("pump"));
    EXPECT_FALSE(outcome.passed());
    const CheckResult* energy = find_check(outcome, "pump", "energy_drift");
    ASSERT_NE(energy, nullptr);
    EXPECT_EQ(energy->status, CheckStatus::fail);
    EXPECT_NE(energy->detail.find("relative kinetic-energy drift"), std::string::npos) << energy->detail;
    EXPECT_NE(energy->detail.find("exceeds the tolerance"), std::string::npos) << energy->detail;
    // Output times 0, 0.05, ..., 0.2: K(0) is measured after the first advance (to t = 0), then
    // four more advances each scale the speed by 1.01, so K grows by the factor 1.01^8 and the
    // drift, relative to the largest K, is (1.01^8 - 1) / 1.01^8.
    EXPECT_NEAR(energy->value, (std::pow(1.01, 8) - 1) / std::pow(1.01, 8), 1e-9);
    EXPECT_EQ(find_check(outcome, "good", "energy_drift")->status, CheckStatus::pass);
}

TEST(ValidationRunner, ThrowingCrashingHangingAndNanCasesFailButTheSuiteGoesOn) {
    const auto suite = test_suite(two_disk_scene(), {"throws", "crashes", "hangs", "nan", "good"});
    const auto outcome = run(suite,
                             {test_backend("throws", Fault::throws), test_backend("crashes", Fault::crashes),
                              test_backend("hangs", Fault::hangs), test_backend("nan", Fault::produces_nan),
                              test_backend("good", Fault::none)},
                             fresh_output_dir("faults"));
    ASSERT_EQ(outcome.cases.size(), 10u);
    std::map<std::string, RunStatus> status;
    for (const auto& c : outcome.cases) status[c.spec.backend] = c.status;
    EXPECT_EQ(status["throws"], RunStatus::error);
    EXPECT_EQ(status["crashes"], RunStatus::crashed);
    EXPECT_EQ(status["hangs"], RunStatus::timed_out);
    EXPECT_EQ(status["nan"], RunStatus::error);
    EXPECT_EQ(status["good"], RunStatus::completed);
    EXPECT_NE(find_check(outcome, "throws", "run")->detail.find("deliberate failure"), std::string::npos);
    EXPECT_NE(find_check(outcome, "crashes", "run")->detail.find("signal"), std::string::npos);
    EXPECT_NE(find_check(outcome, "nan", "run")->detail.find("NaN"), std::string::npos);
    EXPECT_EQ(find_check(outcome, "good", "run")->status, CheckStatus::pass);
    EXPECT_FALSE(outcome.passed());
}

TEST(ValidationRunner, ResumeSkipsFinishedCasesAndRunsMissingOnes) {
    const auto suite = test_suite(two_disk_scene(), {"good"});
    const std::string dir = fresh_output_dir("resume");
    const auto first = run(suite, {test_backend("good", Fault::none)}, dir);
    ASSERT_EQ(first.cases_run, 2u);
    std::filesystem::remove(dir + "/cases/" + first.cases[1].spec.id + ".toml");
    const auto second = run(suite, {test_backend("good", Fault::none)}, dir, true);
    EXPECT_EQ(second.cases_resumed, 1u);
    EXPECT_EQ(second.cases_run, 1u);
    EXPECT_TRUE(second.passed());
    // A resumed run judges the old measurements the same way as the fresh ones.
    EXPECT_EQ(first.checks.size(), second.checks.size());
}

// What --resume printed, and its outcome.
std::pair<validation::SuiteOutcome, std::string> resume(const validation::Suite& suite, const std::string& dir,
                                                        const std::vector<BackendInfo>& backends = {
                                                            test_backend("good", Fault::none)}) {
    std::FILE* progress = std::tmpfile();
    validation::RunnerOptions options;
    options.output_dir = dir;
    options.jobs = 2;
    options.resume = true;
    options.progress = progress;
    auto outcome = validation::run_suite(suite, backends, options);
    std::rewind(progress);
    std::string text;
    for (int c; (c = std::fgetc(progress)) != EOF;) text += char(c);
    std::fclose(progress);
    return {std::move(outcome), text};
}

// A resumed run kept the cases of an earlier run whatever had changed since (the scene, the
// suite's duration): it said "passed" where a fresh run fails. A case is kept only when its
// definition (validation/plan/case_definition.h) is unchanged, and the terminal says how many
// ran again and why.
TEST(ResumeRerunsChangedCases, AChangedSceneOrSuiteEntryRunsTheCaseAgainAndSaysWhy) {
    auto suite = test_suite(two_disk_scene(), {"good"});
    const std::string dir = fresh_output_dir("resume_changed");
    ASSERT_EQ(run(suite, {test_backend("good", Fault::none)}, dir).cases_run, 2u);
    const auto unchanged = resume(suite, dir);
    EXPECT_EQ(unchanged.first.cases_resumed, 2u);
    EXPECT_EQ(unchanged.second.find("rerun"), std::string::npos) << unchanged.second;

    suite.scenes[0].scene->generators[0].disks[0].vx = 2;  // the scene changed
    const auto scene = resume(suite, dir);
    EXPECT_EQ(scene.first.cases_run, 2u);
    EXPECT_EQ(scene.first.cases_resumed, 0u);
    EXPECT_NE(scene.second.find("resume: 2 cases rerun: scene file changed (2)"), std::string::npos) << scene.second;
    EXPECT_EQ(scene.first.cases[0].initial.vx[0], 2);

    suite.scenes[0].duration = 0.1;  // the suite entry's duration changed
    const auto duration = resume(suite, dir);
    EXPECT_EQ(duration.first.cases_run, 2u);
    EXPECT_NE(duration.second.find("resume: 2 cases rerun: duration changed (2)"), std::string::npos) << duration.second;
    EXPECT_EQ(duration.first.cases[0].duration, 0.1);
    EXPECT_EQ(resume(suite, dir).first.cases_resumed, 2u);  // and kept once it ran so
}

// A case killed at the time limit (a slow hour, a runner stopped with SIGSTOP) is no verdict on
// the case: --resume runs it again and says so, and keeps the cases that finished.
TEST(ResumeRerunsChangedCases, ACaseThatTimedOutRunsAgain) {
    const auto suite = test_suite(two_disk_scene(), {"good", "hangs"});
    const std::vector<BackendInfo> backends = {test_backend("good", Fault::none), test_backend("hangs", Fault::hangs)};
    const std::string dir = fresh_output_dir("resume_timed_out");
    const auto first = run(suite, backends, dir);
    ASSERT_EQ(first.cases_run, 4u);
    const auto [second, text] = resume(suite, dir, backends);
    EXPECT_EQ(second.cases_resumed, 2u) << "the finished cases are kept";
    EXPECT_EQ(second.cases_run, 2u) << "the timed-out ones run again";
    EXPECT_NE(text.find("resume: 2 cases rerun: timed out before (2)"), std::string::npos) << text;
    for (const auto& c : second.cases)
        EXPECT_EQ(c.status, c.spec.backend == "hangs" ? RunStatus::timed_out : RunStatus::completed) << c.spec.id;
}

TEST(ValidationRunner, RefusedSceneAndInapplicableChecksAreListedWithReasons) {
    Scene scene = two_disk_scene();
    scene.world.boundary = Boundary::reflect;  // reflecting walls: momentum is not conserved
    const auto suite = test_suite(scene, {"good", "picky"});
    const auto outcome = run(suite, {test_backend("good", Fault::none), test_backend("picky", Fault::none, "no walls here")},
                             fresh_output_dir("leftout"));
    const CheckResult* momentum = find_check(outcome, "good", "momentum_drift");
    ASSERT_NE(momentum, nullptr);
    EXPECT_EQ(momentum->status, CheckStatus::left_out);
    EXPECT_NE(momentum->detail.find("reflecting walls"), std::string::npos);
    const CheckResult* refused = find_check(outcome, "picky", "run");
    ASSERT_NE(refused, nullptr);
    EXPECT_EQ(refused->status, CheckStatus::left_out);
    EXPECT_NE(refused->detail.find("no walls here"), std::string::npos);
    EXPECT_TRUE(outcome.passed());  // left out is not failed
}

TEST(ValidationRunner, WritesSummaryAndJUnitFiles) {
    const auto suite = test_suite(two_disk_scene(), {"good", "pump"});
    const std::string dir = fresh_output_dir("files");
    run(suite, {test_backend("good", Fault::none), test_backend("pump", Fault::adds_energy)}, dir);
    std::ifstream junit(dir + "/junit.xml");
    std::stringstream text;
    text << junit.rdbuf();
    EXPECT_NE(text.str().find("<failure message=\"relative kinetic-energy drift"), std::string::npos);
    EXPECT_NE(text.str().find("<skipped"), std::string::npos);
    ASSERT_TRUE(std::filesystem::exists(dir + "/summary.json"));
    // The check table's order and metadata, for the report (check_table.h).
    std::ifstream summary_file(dir + "/summary.json");
    std::stringstream summary;
    summary << summary_file.rdbuf();
    std::size_t at = summary.str().find("\"check_definitions\"");
    ASSERT_NE(at, std::string::npos);
    for (const validation::CheckDefinition& c : validation::check_table) {
        at = summary.str().find(std::string("\"name\": \"") + c.name + "\"", at);
        ASSERT_NE(at, std::string::npos) << c.name << " missing, or out of the table's order";
        const std::size_t key = summary.str().find(std::string("\"tolerance_key\": \"") + c.tolerance_key + "\"", at);
        EXPECT_NE(key, std::string::npos) << c.name;
    }
}

TEST(ValidationRunner, UnknownBackendIsAnErrorNamingTheSuite) {
    const auto suite = test_suite(two_disk_scene(), {"nonexistent"});
    try {
        run(suite, {test_backend("good", Fault::none)}, fresh_output_dir("unknown"));
        FAIL() << "expected a SuiteError";
    } catch (const validation::SuiteError& e) {
        EXPECT_NE(std::string(e.what()).find("test-suite"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("nonexistent"), std::string::npos);
    }
}

}  // namespace
}  // namespace collide::test
