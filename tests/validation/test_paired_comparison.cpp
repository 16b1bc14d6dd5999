// The many-body scenes compared with the reference seed by seed (validation/compare/
// reference_comparison.cpp, "paired_statistic"): a cooling gas by Haff's cooling time, a scene
// whose Z is left out by its collision rate; and the default suite, whose every scene a
// non-reference backend runs is compared with the reference unless the reference refuses it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "validation/compare/reference_comparison.h"
#include "validation/plan/case_plan.h"
#include "validation/plan/suite.h"

namespace collide::validation {
namespace {

constexpr double kDuration = 1.0, kDisks = 1000;

// The seeds' own cooling times scatter by 5 %, far more than the 1 % a backend adds: only a
// comparison paired by seed resolves that 1 %.
constexpr double kSeedScatter[6] = {-0.05, 0.04, 0.0, 0.05, -0.03, -0.01};

// A run whose kinetic energy follows Haff's law K(t) = K0 / (1 + t / tau)^2 exactly, at 11
// output times, with `contacts` collisions.
CaseResult cooling_run(const std::string& backend, bool reference, std::uint64_t seed, double tau, double contacts) {
    CaseResult r;
    r.spec.scene = "gas";
    r.spec.backend = backend;
    r.spec.reference = reference;
    r.spec.seed = seed;
    if (!reference) r.spec.dt = 1e-3;
    r.spec.id = "gas__" + backend + (reference ? "" : "__dt0.001") + "__seed" + std::to_string(seed);
    r.disks = std::size_t(kDisks);
    r.total_mass = kDisks;
    r.duration = kDuration;
    r.dt = 1e-3;
    r.contacts = std::int64_t(contacts);
    for (int k = 0; k <= 10; ++k) {
        Metrics m;
        m.time = 0.1 * k;
        m.kinetic_energy = 1000.0 / std::pow(1 + m.time / tau, 2);
        r.series.push_back(m);
    }
    r.final_state.vx = {1.0, -1.0};
    r.final_state.vy = {0.0, 0.0};
    return r;
}

// Six seeds of `event` and of `step`, the stepped runs `offset` (relative) off in tau and in the
// contacts, listed in the reverse order of their seeds (pairs are found by seed, not by place).
std::vector<CaseResult> runs(double offset) {
    std::vector<CaseResult> out;
    for (std::uint64_t s = 1; s <= 6; ++s)
        out.push_back(cooling_run("event", true, s, 15 * (1 + kSeedScatter[s - 1]), 700 * (1 + kSeedScatter[s - 1])));
    for (std::uint64_t s = 6; s >= 1; --s)
        out.push_back(cooling_run("step", false, s, 15 * (1 + kSeedScatter[s - 1]) * (1 + offset),
                                  700 * (1 + kSeedScatter[s - 1]) * (1 + offset)));
    return out;
}

Comparisons judge(const SceneFeatures& features, double offset) {
    Suite suite;
    SuiteScene entry;
    entry.name = "gas";
    entry.comparison = Comparison::statistics;
    suite.scenes = {entry};
    std::map<std::string, Tolerances> tol;
    tol["event"].statistics_z = 4;
    tol["step"].statistics_z = 4;
    const std::map<std::string, const BackendInfo*> declared = {{"event", &find_backend("event")},
                                                                {"step", &find_backend("step")}};
    return compare_with_reference(suite, runs(offset), {features}, tol, declared);
}

TEST(PairedComparison, ACoolingGasIsJudgedByItsCoolingTimeSeedBySeed) {
    SceneFeatures cooling;
    cooling.restitution = 0.9;
    const Comparisons c = judge(cooling, 0.01);
    ASSERT_EQ(c.work_precision.size(), 1u);
    const WorkPrecisionLine& line = c.work_precision[0];
    EXPECT_EQ(line.error_kind, "|tau - tau_ref| / tau_ref");
    ASSERT_EQ(line.points.size(), 1u);
    const WorkPrecisionPoint& p = line.points[0];
    ASSERT_TRUE(p.paired);
    EXPECT_TRUE(p.paired->paired);
    EXPECT_EQ(p.paired->replicates, 6u);
    // Every seed is 1 % slower to cool: the per-seed differences are 0.15 * (1 + scatter), their
    // mean 0.15 * (1 + mean scatter) over the reference's mean 15 * (1 + mean scatter).
    EXPECT_NEAR(p.paired->relative, 0.01, 1e-6);
    EXPECT_NEAR(p.error, 0.01, 1e-6);
    // The per-seed differences scatter only by the seeds' 1 % of 5 %: an SE near 2e-4, where the
    // replicate means' scatter (5 % / sqrt(6) ~ 2 %) would hide the 1 % altogether.
    EXPECT_LT(p.paired->relative_standard_error, 1e-3);
    EXPECT_GT(p.paired->standard_error / p.paired->mean, 5e-3);
    EXPECT_TRUE(p.paired->resolved);
    EXPECT_NEAR(p.paired->sigmas, std::fabs(p.paired->difference) / p.paired->difference_standard_error, 1e-9);
    EXPECT_DOUBLE_EQ(p.error_standard_error, p.paired->relative_standard_error);
}

TEST(PairedComparison, AnExactCopyHasNoDifference) {
    SceneFeatures cooling;
    cooling.restitution = 0.9;
    const auto judged = judge(cooling, 0.0);  // kept: p refers into it
    const WorkPrecisionPoint& p = judged.work_precision[0].points[0];
    ASSERT_TRUE(p.paired);
    EXPECT_NEAR(p.paired->relative, 0.0, 1e-12);
    EXPECT_FALSE(p.paired->resolved);
}

TEST(PairedComparison, ASceneWithoutZIsJudgedByItsCollisionRate) {
    SceneFeatures stones;
    stones.reflecting_walls = true;
    stones.stones = true;
    stones.uniform_radius = false;  // Z left out: no one contact distance
    const Comparisons c = judge(stones, 0.02);
    ASSERT_EQ(c.work_precision.size(), 1u);
    EXPECT_EQ(c.work_precision[0].error_kind, "|nu - nu_ref| / nu_ref");
    const WorkPrecisionPoint& p = c.work_precision[0].points[0];
    ASSERT_TRUE(p.paired);
    EXPECT_FALSE(p.pressure);
    // The contact counts are rounded to integers: 2 % up to about 1e-3.
    EXPECT_NEAR(p.paired->relative, 0.02, 2e-3);
}

TEST(PairedComparison, AnElasticGasWithZKeepsItsZLine) {
    const Comparisons c = judge(SceneFeatures{}, 0.0);
    for (const WorkPrecisionLine& line : c.work_precision) {
        EXPECT_EQ(line.error_kind, "|Z - Z_ref| / Z_ref");
        for (const WorkPrecisionPoint& p : line.points) EXPECT_FALSE(p.paired);
    }
}

// Every scene of the default suite that a backend not exact runs is compared
// with the reference, unless the reference cannot run it: a stepped backend earns a "use for" or
// "not for" on every such scene (accuracy_verdicts.h), not "checked only".
TEST(DefaultSuite, EverySceneAnInexactBackendRunsIsComparedWithTheReferenceWhereItCanRun) {
    const Suite suite = load_suite(COLLIDE_SOURCE_DIR "/validation/suites/default.toml");
    const std::vector<Scene> scenes = load_suite_scenes(suite);
    const std::vector<BackendInfo> backends = select_backends(suite, all_backends());
    std::set<std::string> not_exact;  // the exact solvers (event-plain) are held to physics and to event
    for (const BackendInfo& b : backends)
        if (!b.exact) not_exact.insert(b.name);
    std::set<std::size_t> run_by_others;
    for (const CaseSpec& c : plan_cases(suite, scenes, backends))
        if (not_exact.count(c.backend)) run_by_others.insert(c.scene_index);
    const BackendInfo& reference = find_backend(suite.reference);
    for (std::size_t i : run_by_others) {
        const SuiteScene& entry = suite.scenes[i];
        if (reference.supports(scenes[i])) continue;  // the reference refuses it: checked only, with the reason
        EXPECT_NE(entry.comparison, Comparison::none) << entry.name << " is run by a stepped backend and by "
                                                      << suite.reference << " but compared with nothing";
    }
    for (const char* name : {"inelastic_gas", "stones_and_gas"}) {
        const auto it = std::find_if(suite.scenes.begin(), suite.scenes.end(),
                                     [&](const SuiteScene& s) { return s.name == name; });
        ASSERT_NE(it, suite.scenes.end()) << name;
        EXPECT_EQ(it->comparison, Comparison::statistics) << name;
        EXPECT_GE(it->seeds.size(), 4u) << name << ": several seeds for an error bar";
        EXPECT_FALSE(reference.supports(scenes[std::size_t(it - suite.scenes.begin())])) << name;
    }
}

}  // namespace
}  // namespace collide::validation
