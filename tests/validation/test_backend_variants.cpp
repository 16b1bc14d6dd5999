// One backend twice in one suite: `box2d` and `box2d[shipped]` are separate backends with their
// own settings, cases, result files, tolerances and report columns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "box2d/box2d_solver.h"
#include "test_backends.h"
#include "validation/run/case_isolation.h"
#include "validation/plan/backend_variant.h"
#include "validation/plan/case_plan.h"
#include "validation/suite_runner.h"

namespace collide::validation {
namespace {

BackendInfo box2d_backend() {
    return {"box2d", "float", "Box2D", box2d_supports,
            [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<Box2dSolver>(); }};
}

// Equal disks meeting head-on at relative speed 0.5, below Box2D's shipped restitution
// threshold (1 m/s; radius 0.5 maps 1:1 in both presets): tuned bounces, shipped stops dead.
Scene slow_head_on() {
    Scene s = test::two_disk_scene("slow_head_on");
    s.run.duration = 3.0;
    s.run.output_interval = 0.5;
    s.generators[0].disks = {{4, 5, 0.25, 0, 0.5, 1, false}, {6, 5, -0.25, 0, 0.5, 1, false}};
    return s;
}

Suite suite_with_shipped(const std::vector<std::string>& backends) {
    Suite suite = test::test_suite(slow_head_on(), backends);
    suite.seeds = {1};
    suite.variants = {{"box2d[shipped]", "box2d", {{"preset", "shipped"}}, {}, {}}};
    return suite;
}

const CheckResult* find_check(const SuiteOutcome& o, const std::string& backend, const std::string& check) {
    for (const auto& c : o.checks)
        if (c.backend == backend && c.check == check) return &c;
    return nullptr;
}

std::string file_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(BackendVariants, SuiteFileDeclaresAVariantAndItsTolerances) {
    const auto dir = std::filesystem::path(test::fresh_output_dir("variant_suite"));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "gas.toml") << "# placeholder\n";
    const Suite suite = parse_suite(R"(
scene_dir = "."
[variant."box2d[shipped]"]
preset = "shipped"
velocity_iterations = 10
[tolerances."box2d[shipped]"]
energy_drift = 0.5
[[scene]]
name = "gas"
)", "suites/v.toml", dir.string());
    ASSERT_EQ(suite.variants.size(), 1u);
    EXPECT_EQ(suite.variants[0].label, "box2d[shipped]");
    EXPECT_EQ(suite.variants[0].base, "box2d");
    EXPECT_EQ(suite.variants[0].settings.at("preset"), "shipped");
    EXPECT_EQ(suite.variants[0].settings.at("velocity_iterations"), "10");
    // A variant inherits what its base declares (box2d's own limits), then the overrides.
    const BackendInfo variant = variant_backend(find_backend("box2d"), suite.variants[0]);
    EXPECT_EQ(variant.name, "box2d[shipped]");
    const Tolerances shipped = suite.tolerances.for_backend(variant);
    EXPECT_EQ(shipped.energy_drift, 0.5);
    // Everything not overridden is the base backend's limit, not a float stepper's.
    EXPECT_EQ(shipped.max_overlap, suite.tolerances.for_backend(find_backend("box2d")).max_overlap);
    EXPECT_NE(shipped.max_overlap, suite.tolerances.for_backend(find_backend("cpu")).max_overlap);
}

TEST(BackendVariants, LeaveOutNeedsAReasonAndKnownCheckNames) {
    const auto dir = std::filesystem::path(test::fresh_output_dir("variant_leave_out"));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "gas.toml") << "# placeholder\n";
    const auto parse = [&](const std::string& keys) {
        return parse_suite("scene_dir = \".\"\n[variant.\"box2d[shipped]\"]\npreset = \"shipped\"\n" + keys +
                               "[[scene]]\nname = \"gas\"\n",
                           "suites/v.toml", dir.string());
    };
    const Suite suite = parse("leave_out = [\"pressure\", \"speed_distribution\"]\nleave_out_reason = \"cools\"\n");
    EXPECT_EQ(suite.variants[0].leave_out, (std::vector<std::string>{"pressure", "speed_distribution"}));
    EXPECT_EQ(suite.variants[0].leave_out_reason, "cools");
    EXPECT_EQ(suite.variants[0].settings.count("leave_out"), 0u) << "not a key for the backend";
    const auto error_of = [&](const std::string& keys) {
        try {
            parse(keys);
        } catch (const SuiteError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(error_of("leave_out = [\"pressure\"]\n").find("leave_out_reason"), std::string::npos);
    EXPECT_NE(error_of("leave_out = [\"presure\"]\nleave_out_reason = \"x\"\n").find("collision_rate"),
              std::string::npos);
}

TEST(BackendVariants, LeftOutChecksKeepTheirValueAndCarryTheReason) {
    std::vector<CheckResult> checks(3);
    checks[0].backend = "box2d[shipped]", checks[0].check = "pressure", checks[0].status = CheckStatus::fail;
    checks[0].value = 40.1;
    checks[1].backend = "box2d[shipped]", checks[1].check = "energy_drift", checks[1].status = CheckStatus::fail;
    checks[2].backend = "box2d", checks[2].check = "pressure", checks[2].status = CheckStatus::fail;
    BackendVariant shipped{"box2d[shipped]", "box2d", {{"preset", "shipped"}}, {"pressure"}, "cools"};
    apply_variant_leave_outs(checks, {shipped});
    EXPECT_EQ(checks[0].status, CheckStatus::left_out);
    EXPECT_EQ(checks[0].detail, "cools");
    EXPECT_EQ(checks[0].value, 40.1);
    EXPECT_EQ(checks[1].status, CheckStatus::fail) << "not named: still judged";
    EXPECT_EQ(checks[2].status, CheckStatus::fail) << "the base backend is not the variant";
}

TEST(BackendVariants, BadLabelNamesTheShapeExpected) {
    const auto dir = test::fresh_output_dir("variant_bad");
    std::filesystem::create_directories(dir);
    std::ofstream(std::filesystem::path(dir) / "gas.toml") << "# placeholder\n";
    for (const char* label : {"box2d", "box2d[]", "[shipped]", "box2d[Shipped]", "box2d[a b]"}) {
        const std::string text = std::string("scene_dir = \".\"\n[variant.\"") + label +
                                 "\"]\npreset = \"shipped\"\n[[scene]]\nname = \"gas\"\n";
        try {
            parse_suite(text, "suites/bad.toml", dir);
            ADD_FAILURE() << "no error for " << label;
        } catch (const SuiteError& e) {
            EXPECT_NE(std::string(e.what()).find("backend[name]"), std::string::npos) << e.what();
        }
    }
}

TEST(BackendVariants, UnknownVariantOrMissingBaseIsAnError) {
    EXPECT_THROW(select_backends(suite_with_shipped({"box2d[tuned]"}), {box2d_backend()}), SuiteError);
    EXPECT_THROW(select_backends(suite_with_shipped({"box2d[shipped]"}), {}), SuiteError);
    // With "all", a variant whose base this build lacks is left out like the base itself.
    EXPECT_TRUE(select_backends(suite_with_shipped({"all"}), {}).empty());
}

TEST(BackendVariants, TwoConfigurationsGetDistinctCasesFilesChecksAndColumns) {
    const Suite suite = suite_with_shipped({"all"});
    const std::string dir = test::fresh_output_dir("variants_run");
    RunnerOptions options;
    options.output_dir = dir;
    options.jobs = 1;
    const SuiteOutcome outcome = run_suite(suite, {box2d_backend()}, options);

    ASSERT_EQ(outcome.cases.size(), 2u);
    EXPECT_EQ(outcome.cases[0].spec.backend, "box2d");
    EXPECT_EQ(outcome.cases[1].spec.backend, "box2d[shipped]");
    EXPECT_NE(outcome.cases[0].spec.id, outcome.cases[1].spec.id);
    // File names carry no brackets (shell globs, URLs): "box2d-shipped".
    EXPECT_EQ(outcome.cases[1].spec.id.find('['), std::string::npos) << outcome.cases[1].spec.id;
    for (const auto& c : outcome.cases) EXPECT_TRUE(std::filesystem::exists(result_path(dir + "/cases", c.spec.id)));
    EXPECT_NE(result_path(dir, outcome.cases[0].spec.id), result_path(dir, outcome.cases[1].spec.id));

    // The variant's settings reached its solver: tuned keeps the energy, shipped loses it all.
    const CheckResult* tuned = find_check(outcome, "box2d", "energy_drift");
    const CheckResult* shipped = find_check(outcome, "box2d[shipped]", "energy_drift");
    ASSERT_NE(tuned, nullptr);
    ASSERT_NE(shipped, nullptr);
    EXPECT_EQ(tuned->status, CheckStatus::pass);
    EXPECT_EQ(shipped->status, CheckStatus::fail);
    EXPECT_NEAR(shipped->value, 1.0, 1e-5);

    // summary.json, which the report reads, names both backends.
    const std::string summary = file_text(dir + "/summary.json");
    EXPECT_NE(summary.find("\"backend\": \"box2d[shipped]\""), std::string::npos);
    EXPECT_NE(summary.find("\"backend\": \"box2d\""), std::string::npos);
}

TEST(BackendVariants, DefaultSuiteRunsBothBox2dConfigurationsWithTheirOwnLimits) {
    const Suite suite = load_suite(COLLIDE_SOURCE_DIR "/validation/suites/default.toml");
    std::map<std::string, BackendInfo> selected;
    for (const BackendInfo& b : select_backends(suite, all_backends())) selected.emplace(b.name, b);
    ASSERT_TRUE(selected.count("box2d"));
    ASSERT_TRUE(selected.count("box2d[shipped]"));
    const Tolerances tuned = suite.tolerances.for_backend(selected.at("box2d"));
    const Tolerances shipped = suite.tolerances.for_backend(selected.at("box2d[shipped]"));
    EXPECT_GT(shipped.energy_drift, tuned.energy_drift);
    // A stated limit, not "anything": a run that loses all its energy still fails.
    EXPECT_LT(shipped.energy_drift, 1.0);
    // Its gas statistics describe a cooling gas: left out with a reason, not given a wide limit.
    const auto variant = std::find_if(suite.variants.begin(), suite.variants.end(),
                                      [](const BackendVariant& v) { return v.label == "box2d[shipped]"; });
    ASSERT_NE(variant, suite.variants.end());
    for (const char* check : {"pressure", "collision_rate", "speed_distribution"})
        EXPECT_NE(std::find(variant->leave_out.begin(), variant->leave_out.end(), check), variant->leave_out.end()) << check;
    EXPECT_EQ(shipped.statistics_z, tuned.statistics_z);
}

// The plain event solver is a second exact solver, held against `event` by the conformance
// tests; a suite's "all" leaves it out (the suites' budget), and a suite that names it runs it.
TEST(BackendVariants, AllLeavesOutThePlainEventSolverWhichASuiteOrASceneCanName) {
    Suite suite = load_suite(COLLIDE_SOURCE_DIR "/validation/suites/default.toml");
    const std::vector<Scene> scenes = load_suite_scenes(suite);
    // "all" leaves event-plain out: it runs only the [[scene]]s that name it.
    std::set<std::string> plain_scenes, named;
    for (const CaseSpec& c : plan_cases(suite, scenes, select_backends(suite, all_backends())))
        if (c.backend == "event-plain") plain_scenes.insert(c.scene);
    for (const SuiteScene& s : suite.scenes)
        if (std::find(s.backends.begin(), s.backends.end(), "event-plain") != s.backends.end()) named.insert(s.name);
    EXPECT_FALSE(named.empty()) << "the default suite compares the two exact solvers";
    EXPECT_EQ(plain_scenes, named);
    suite.backends = {"event", "event-plain"};
    std::vector<std::string> names;
    for (const BackendInfo& b : select_backends(suite, all_backends())) names.push_back(b.name);
    EXPECT_EQ(names, (std::vector<std::string>{"event", "event-plain"}));
}

// Every case goes to a worker process that runs case after case (runs_in_worker;
// validation/run/case_isolation.h). A case's numbers must not depend on what its worker ran
// before: one worker running every case in turn (--jobs 1) gives the same value for every
// check, to the bit, as a worker per case (--jobs = the number of cases).
TEST(BackendVariants, ACaseGivesTheSameNumbersWhateverItsWorkerRanBefore) {
    Suite suite = suite_with_shipped({"all"});
    suite.seeds = {1, 2};
    const std::vector<BackendInfo> backends = all_backends();
    auto run_with_jobs = [&](int jobs) {
        RunnerOptions options;
        options.output_dir = test::fresh_output_dir("worker_history_" + std::to_string(jobs));
        options.jobs = jobs;
        return run_suite(suite, backends, options);
    };
    const SuiteOutcome one_worker = run_with_jobs(1);
    ASSERT_GE(one_worker.cases.size(), 10u);
    const SuiteOutcome worker_each = run_with_jobs(int(one_worker.cases.size()));
    ASSERT_EQ(one_worker.checks.size(), worker_each.checks.size());
    for (std::size_t i = 0; i < one_worker.checks.size(); ++i) {
        const CheckResult& a = one_worker.checks[i];
        const CheckResult& b = worker_each.checks[i];
        ASSERT_EQ(a.subject + a.check, b.subject + b.check);
        EXPECT_EQ(a.status, b.status) << a.subject << " " << a.check;
        if (std::isnan(a.value)) EXPECT_TRUE(std::isnan(b.value)) << a.subject << " " << a.check;
        else EXPECT_EQ(a.value, b.value) << a.subject << " " << a.check;
    }
    for (const CaseResult& c : one_worker.cases) EXPECT_TRUE(runs_in_worker(c.spec));
}

}  // namespace
}  // namespace collide::validation
