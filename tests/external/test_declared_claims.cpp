// What a solver declares (exact, rule, precision) and the limits that follow from it
// (docs/validation.md, "What a solver claims"; docs/your-solver.md, "Declaring an exact
// solver"): a suite's [solver.NAME] keys and their contradictions, a Python class's attributes
// read by its runner, and the rounding-level limits of an exact solver, which fail an exact
// solver whose collisions lose 1 % of the energy and pass `event-plain`.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/run_driver.h"
#include "core/scene/scene_features.h"
#include "core/scene/scene_loader.h"
#include "external/external_solver.h"
#include "validation/judge/checks.h"
#include "validation/record/exact_limits.h"
#include "validation/plan/external_solvers.h"
#include "tests/support/recorded_case.h"
#include "tests/support/suite_text.h"
#include "validation/plan/suite.h"

namespace collide::validation {
namespace {

using test::parse_suite_text;
using test::suite_refusal;

TEST(DeclaredClaims, SuiteKeysDeclareExactAndPrecision) {
    const Suite s = parse_suite_text("[solver.mine]\ncommand = \"x\"\nexact = true\nprecision = \"float\"\n"
                                     "[solver.other]\ncommand = \"y\"\n");
    const auto backends = backends_with_solvers(s, {}, {"python3", "runner.py"});
    ASSERT_EQ(backends.size(), 2u);
    EXPECT_TRUE(backends[0].exact);
    EXPECT_EQ(backends[0].precision, "float");
    EXPECT_TRUE(backends[0].single_precision());
    EXPECT_TRUE(backends[0].claims_to_conserve("energy"));
    EXPECT_FALSE(backends[1].exact);
    EXPECT_EQ(backends[1].precision, "double");  // not declared: double
    EXPECT_FALSE(backends[1].claims_to_conserve("energy"));
}

TEST(DeclaredClaims, AContradictionIsRefusedWithFileAndLine) {
    const std::string both = suite_refusal("[solver.mine]\ncommand = \"x\"\nrule = \"collide-first\"\nexact = true\n");
    EXPECT_NE(both.find("s.toml:4: solver.mine.exact: exact together with rule \"collide-first\""), std::string::npos)
        << both;
    EXPECT_NE(suite_refusal("[solver.mine]\ncommand = \"x\"\nprecision = \"half\"\n").find("s.toml:3: solver.mine.precision"),
              std::string::npos);
    EXPECT_NE(suite_refusal("[solver.mine]\ncommand = \"x\"\nexact = \"yes\"\n").find("s.toml:3: solver.mine.exact: expected true"),
              std::string::npos);
}

// A class's attributes are read by its runner, the same for a suite's `python = ...`,
// --python-solver and collide.validate(solvers=...), all of which meet here.
class ClassDeclarations : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() / ("collide-claims-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
        std::ofstream(dir_ / "solvers.py") << "class Exact:\n    exact = True\n    precision = 'float'\n\n"
                                              "class Stepper:\n    rule = 'integrate-first'\n\n"
                                              "class Plain:\n    pass\n";
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::vector<BackendInfo> join(const std::string& table) const {
        Suite s = parse_suite_text(table);
        for (auto& spec : s.solvers) spec.directory = dir_.string();
        return backends_with_solvers(s, {}, {COLLIDE_PYTHON, std::string(COLLIDE_SOURCE_DIR) + "/python/collide/solver_runner.py"});
    }
    std::filesystem::path dir_;
};

TEST_F(ClassDeclarations, AttributesDeclareWhatTheSuiteDoesNotSay) {
    const auto b = join("[solver.a]\npython = \"solvers.py:Exact\"\n[solver.b]\npython = \"solvers.py:Stepper\"\n"
                        "[solver.c]\npython = \"solvers.py:Plain\"\n");
    ASSERT_EQ(b.size(), 3u);
    EXPECT_TRUE(b[0].exact);
    EXPECT_EQ(b[0].precision, "float");
    EXPECT_EQ(b[1].rule, "integrate-first");
    EXPECT_FALSE(b[1].exact);
    EXPECT_FALSE(b[2].exact);
    EXPECT_FALSE(b[2].stepping_rule());
}

TEST_F(ClassDeclarations, AttributesThatContradictTheSuiteAreRefused) {
    try {
        join("[solver.a]\npython = \"solvers.py:Exact\"\nrule = \"collide-first\"\n");
        ADD_FAILURE() << "exact class with a suite rule accepted";
    } catch (const SuiteError& e) {
        EXPECT_NE(std::string(e.what()).find("exact together with rule"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("solvers.py:Exact"), std::string::npos) << e.what();
    }
    EXPECT_THROW(join("[solver.a]\npython = \"solvers.py:Exact\"\nprecision = \"double\"\n"), SuiteError);
    EXPECT_THROW(join("[solver.a]\npython = \"solvers.py:Missing\"\n"), SuiteError);
}

// --- The limits of an exact solver, on head_on_equal (one head-on collision of equal disks) ---

// Runs `backend` on `given` (the scene it is given) and records the case as the suite
// would, for a case of the scene `declared`.
CaseResult run_case(const BackendInfo& backend, const Scene& declared, const Scene& given) {
    const auto solver = backend.create(BackendOptions{});
    return test::recorded_case(*solver, declared, given, backend.name, backend.name);
}

// The checks of `r` judged as a case of `claims`, with the limits the runner derives.
std::vector<CheckResult> judged(const CaseResult& r, const BackendInfo& claims, const Scene& scene, const CaseResult& reference) {
    const Tolerances limits = ToleranceTable{}.for_case(claims, rounding_scale(r, scene, &reference));
    return case_checks(r, scene_features(scene, generate_initial_state(scene)), limits, claims);
}

const CheckResult& check(const std::vector<CheckResult>& checks, const std::string& name) {
    for (const auto& c : checks)
        if (c.check == name) return c;
    throw std::runtime_error("no check " + name);
}

// An outside solver as a suite declares it (external_backend), with `event`'s dynamics at a
// restitution of 0.995 behind it: a head-on collision of equal disks then loses 1 - e^2 = 1.0 %
// of the kinetic energy, half the fixed limit (2 %) of a solver that declares nothing.
BackendInfo outside(bool exact) {
    external::ExternalSolverSpec spec;
    spec.name = "lossy";
    spec.command = "unused";
    spec.exact = exact;
    BackendInfo info = external::external_backend(spec);
    info.create = find_backend("event").create;
    return info;
}

TEST(ExactLimits, FailALossyExactSolverAndPassEventPlain) {
    const Scene scene = load_scene(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/head_on_equal.toml");
    Scene lossy = scene;
    lossy.physics.restitution = 0.995;
    const CaseResult reference = run_case(find_backend("event"), scene, scene);
    ASSERT_EQ(reference.contacts, 1);  // the reference counts the case's collisions

    const auto plain = judged(run_case(find_backend("event-plain"), scene, scene), find_backend("event-plain"), scene, reference);
    for (const auto& c : plain) EXPECT_NE(c.status, CheckStatus::fail) << c.check << ": " << c.detail;
    EXPECT_LT(check(plain, "energy_drift").tolerance, 1e-13);  // 16 eps (1 + 1) = 7.1e-15

    const CaseResult run = run_case(outside(true), scene, lossy);
    const auto declared_exact = judged(run, outside(true), scene, reference);  // kept: check() points into it
    const CheckResult& energy = check(declared_exact, "energy_drift");
    EXPECT_EQ(energy.status, CheckStatus::fail) << energy.value << " within " << energy.tolerance;
    EXPECT_NEAR(energy.value, 1 - 0.995 * 0.995, 1e-6);
    // The same solver declaring nothing is held to the loose limit, which it passes: the hole
    // the declaration closes.
    EXPECT_EQ(check(judged(run, outside(false), scene, reference), "energy_drift").status, CheckStatus::pass);
}

TEST(ExactLimits, TwoExactSolversOnOneCaseGetEqualLimits) {
    const Scene scene = load_scene(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/head_on_equal.toml");
    const CaseResult reference = run_case(find_backend("event"), scene, scene);
    const RoundingScale scale = rounding_scale(reference, scene, &reference);
    const Tolerances a = ToleranceTable{}.for_case(find_backend("event"), scale);
    const Tolerances b = ToleranceTable{}.for_case(find_backend("event-plain"), scale);
    for (const auto& key : tolerance_keys()) EXPECT_EQ(tolerance_value(a, key), tolerance_value(b, key)) << key;
    // L = 10, r_min = 0.5: 64 eps 10 / 1 = 1.4e-13 of the contact distance.
    EXPECT_DOUBLE_EQ(a.max_overlap, position_epsilons * machine_epsilon(false) * 10 / 1.0);
    // Float's epsilon for a float exact solver.
    BackendInfo single = find_backend("event");
    single.precision = "float";
    EXPECT_GT(ToleranceTable{}.for_case(single, scale).energy_drift, 1e8 * a.energy_drift);
}

}  // namespace
}  // namespace collide::validation
