// The stepped rules' bias model in Z and in the collision rate (validation/models/statistics_bias_model.h)
// and the many-body checks that use it (validation/compare/reference_comparison.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "validation/judge/observables.h"
#include "validation/compare/reference_comparison.h"
#include "validation/models/statistics_bias_model.h"

namespace collide::validation {
namespace {

TEST(StatisticsBiasModel, PressureBiasByHand) {
    // nu = 2.5 collisions per disk per time, h = 0.01, shell s = 0.05, c_Z = 1 +- 0.1:
    // Delta Z = nu h / (4 s (2 + s)) = 0.025 / 0.41 = 0.0609756...
    const StatisticsBiasConstants c{1.0, 0.1, 1.0, 0.2};
    const BiasPrediction p = predicted_pressure_bias(2.5, 0.0, 0.01, 0.05, c);
    EXPECT_NEAR(p.value, 0.025 / 0.41, 1e-15);
    EXPECT_NEAR(p.uncertainty, 0.1 * 0.025 / 0.41, 1e-15);
    // The reference's error in nu (2 %) adds in quadrature to c_Z's (10 %).
    const BiasPrediction q = predicted_pressure_bias(2.5, 0.05, 0.01, 0.05, c);
    EXPECT_NEAR(q.uncertainty, std::hypot(0.1, 0.02) * 0.025 / 0.41, 1e-15);
}

TEST(StatisticsBiasModel, CollisionRateBiasByHand) {
    // Delta nu = -c_nu nu^2 h / 2 = -(2.5^2)(0.01)/2 = -0.03125; fewer collisions, never more.
    const StatisticsBiasConstants c{1.0, 0.1, 1.0, 0.2};
    const BiasPrediction p = predicted_collision_rate_bias(2.5, 0.0, 0.01, c);
    EXPECT_DOUBLE_EQ(p.value, -0.03125);
    EXPECT_DOUBLE_EQ(p.uncertainty, 0.2 * 0.03125);
}

// The model judges the backends that declare a stepping rule (BackendInfo::rule).
TEST(StatisticsBiasModel, SteppedBackendsDeclareTheRule) {
    EXPECT_TRUE(find_backend("step").stepping_rule());
    EXPECT_TRUE(find_backend("cpu").stepping_rule());
    EXPECT_TRUE(find_backend("opencl").stepping_rule());
    EXPECT_FALSE(find_backend("event").stepping_rule());
    EXPECT_FALSE(find_backend("event-plain").stepping_rule());
    EXPECT_FALSE(find_backend("box2d").stepping_rule());
}

// A many-body group of four replicates: each replicate's Z is `z` plus a small spread, and its
// contact count gives the collision rate `nu` plus a spread (1000 disks, 10 time units).
constexpr double kDuration = 10, kDisks = 1000, kDt = 0.01;

void add_group(std::vector<CaseResult>& out, const std::string& backend, bool reference, double z, double nu) {
    const double spread[4] = {-0.003, 0.003, -0.001, 0.001};
    for (int k = 0; k < 4; ++k) {
        CaseResult r;
        r.spec.scene = "gas";
        r.spec.backend = backend;
        r.spec.reference = reference;
        r.spec.seed = std::uint64_t(k + 1);
        if (!reference) r.spec.dt = kDt;
        r.spec.id = "gas__" + backend + (reference ? "" : "__dt0.01") + "__seed" + std::to_string(k + 1);
        r.disks = std::size_t(kDisks);
        r.duration = kDuration;
        r.dt = kDt;
        r.compressibility = {z + spread[k], z + spread[k]};
        // collision_rate = 2 contacts / (N T)
        r.contacts = std::int64_t(std::llround((nu + spread[k]) * kDisks * kDuration / 2));
        r.final_state.vx = {1.0, -1.0};
        r.final_state.vy = {0.0, 0.0};
        out.push_back(r);
    }
}

const CheckResult& find(const Comparisons& c, const std::string& backend, const std::string& check) {
    for (const auto& r : c.checks)
        if (r.backend == backend && r.check == check) return r;
    throw std::runtime_error("no " + check + " check for " + backend);
}

// Judges groups of `backend` whose Z and rate differ from the reference's by the given amounts.
Comparisons judge(const std::string& backend, double dz, double dnu) {
    Suite suite;
    SuiteScene entry;
    entry.name = "gas";
    entry.comparison = Comparison::statistics;
    suite.scenes = {entry};
    std::vector<CaseResult> results;
    add_group(results, "event", true, 2.0, 2.5);
    add_group(results, backend, false, 2.0 + dz, 2.5 + dnu);
    std::map<std::string, Tolerances> tol;
    tol["event"].statistics_z = 4;
    tol[backend].statistics_z = 4;
    // What each backend declares: the test's backends by the registry's entries of their names.
    const std::map<std::string, const BackendInfo*> declared = {{"event", &find_backend("event")},
                                                                {backend, &find_backend(backend)}};
    return compare_with_reference(suite, results, {SceneFeatures{}}, tol, declared);
}

TEST(StatisticsBiasCheck, SteppedBackendPassesAtThePredictedBiasAndFailsAtTwiceOrHalf) {
    const BiasPrediction z = predicted_pressure_bias(2.5, 0.0, kDt, contact_shell);
    const BiasPrediction nu = predicted_collision_rate_bias(2.5, 0.0, kDt);
    ASSERT_GT(z.value, 0);
    ASSERT_LT(nu.value, 0);

    const Comparisons at = judge("step", z.value, nu.value);
    const CheckResult& p = find(at, "step", "pressure");
    EXPECT_EQ(p.status, CheckStatus::pass) << p.detail;
    ASSERT_FALSE(std::isnan(p.predicted));
    ASSERT_FALSE(std::isnan(p.predicted_uncertainty));
    EXPECT_NEAR(p.predicted, z.value, 1e-3 * z.value);  // nu_ref from the rounded contact counts
    EXPECT_GT(p.predicted_uncertainty, 0);
    // The bias itself is resolved: a test of equal means would fail here.
    EXPECT_GT(z.value / 0.003, 4);
    EXPECT_EQ(find(at, "step", "collision_rate").status, CheckStatus::pass)
        << find(at, "step", "collision_rate").detail;
    ASSERT_FALSE(std::isnan(find(at, "step", "collision_rate").predicted));

    for (double factor : {2.0, 0.5}) {
        const Comparisons off = judge("cpu", factor * z.value, factor * nu.value);
        EXPECT_EQ(find(off, "cpu", "pressure").status, CheckStatus::fail) << "factor " << factor;
    }
    // Twice the rate bias: 0.031 away from a prediction known to 0.005 (c_nu's 20 %).
    EXPECT_EQ(find(judge("opencl", z.value, 2 * nu.value), "opencl", "collision_rate").status, CheckStatus::fail);
    // No bias at all is wrong for a stepped rule once the bias is resolved.
    EXPECT_EQ(find(judge("step", 0.0, 0.0), "step", "pressure").status, CheckStatus::fail);
}

TEST(StatisticsBiasCheck, NonSteppedBackendKeepsThePlainZCheck) {
    const BiasPrediction z = predicted_pressure_bias(2.5, 0.0, kDt, contact_shell);
    // box2d with the stepped rules' bias: equal means are tested, and a resolved bias fails.
    const Comparisons biased = judge("box2d", z.value, 0.0);
    const CheckResult& p = find(biased, "box2d", "pressure");
    EXPECT_EQ(p.status, CheckStatus::fail) << p.detail;
    EXPECT_TRUE(std::isnan(p.predicted));
    EXPECT_TRUE(std::isnan(find(biased, "box2d", "collision_rate").predicted));
    // ... and equal means pass with a z-score of 0.
    const Comparisons equal = judge("box2d", 0.0, 0.0);
    EXPECT_EQ(find(equal, "box2d", "pressure").status, CheckStatus::pass);
    EXPECT_NEAR(find(equal, "box2d", "pressure").value, 0.0, 1e-12);
}

}  // namespace
}  // namespace collide::validation
