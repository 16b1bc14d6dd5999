// The statistics behind pass/fail: convergence-order fits, z-scores, the KS test.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "validation/judge/statistics.h"
#include "validation/record/exact_limits.h"
#include "validation/record/tolerances.h"

namespace collide::validation {
namespace {

TEST(Statistics, LogLogFitRecoversTheOrderOfSyntheticData) {
    std::vector<double> h, e;
    for (double dt : {1e-2, 5e-3, 2.5e-3, 1.25e-3}) {
        h.push_back(dt);
        e.push_back(3.0 * dt * dt);  // second order
    }
    const auto fit = log_log_fit(h, e);
    ASSERT_TRUE(fit);
    EXPECT_NEAR(fit->slope, 2.0, 1e-12);
    EXPECT_NEAR(std::exp(fit->intercept), 3.0, 1e-9);
}

TEST(Statistics, LogLogFitWithNoiseIsCloseAndSkipsZeroErrors) {
    std::vector<double> h = {0.1, 0.05, 0.025, 0.0125, 0.01};
    std::vector<double> e = {0.1 * 1.05, 0.05 * 0.97, 0.025 * 1.02, 0.0125 * 0.99, 0.0};
    const auto fit = log_log_fit(h, e);
    ASSERT_TRUE(fit);
    EXPECT_NEAR(fit->slope, 1.0, 0.05);
}

TEST(Statistics, LogLogFitIsUndefinedWithTooFewDistinctPoints) {
    EXPECT_FALSE(log_log_fit({0.1, 0.05}, {1, 2}));
    EXPECT_FALSE(log_log_fit({0.1, 0.1, 0.1}, {1, 2, 3}));
    EXPECT_FALSE(log_log_fit({0.1, 0.05, 0.02}, {0, 0, 0}));
}

// Points exactly on a line with equal error bars s on log(y): the slope's standard error is the
// textbook s / sqrt(sum (log x - mean log x)^2) (chi^2 = 0, so no Birge scaling).
TEST(Statistics, WeightedLogLogFitGivesTheSlopesStandardErrorFromTheErrorBars) {
    const std::vector<double> h = {0.1, 0.05, 0.025, 0.0125};
    std::vector<double> e, e_error;
    for (double dt : h) e.push_back(2.0 * dt), e_error.push_back(0.01 * 2.0 * dt);  // s = 0.01 in log(y)
    double mean = 0, sxx = 0;
    for (double dt : h) mean += std::log(dt) / 4;
    for (double dt : h) sxx += (std::log(dt) - mean) * (std::log(dt) - mean);
    // Equal error bars: the weighted and the ordinary fit are the same line, same error.
    for (FitWeights weights : {FitWeights::error_bars, FitWeights::none}) {
        const auto fit = log_log_fit(h, e, 3, e_error, weights);
        ASSERT_TRUE(fit);
        EXPECT_EQ(fit->weighted, weights == FitWeights::error_bars);
        EXPECT_NEAR(fit->slope, 1.0, 1e-12);
        EXPECT_NEAR(fit->slope_standard_error, 0.01 / std::sqrt(sxx), 1e-12);
    }
}

// A point with a wide error bar barely moves a weighted fit; it pulls an unweighted one.
TEST(Statistics, WeightedLogLogFitFollowsThePreciseOnes) {
    const std::vector<double> h = {0.1, 0.05, 0.025, 0.0125};
    const std::vector<double> e = {0.01, 0.0025, 0.000625, 0.0005};  // second order but the last point
    const std::vector<double> precise_but_last = {1e-5, 2.5e-6, 6.25e-7, 0.0005};
    const auto weighted = log_log_fit(h, e, 3, precise_but_last, FitWeights::error_bars);
    const auto unweighted = log_log_fit(h, e, 3);
    ASSERT_TRUE(weighted && unweighted);
    EXPECT_NEAR(weighted->slope, 2.0, 0.01);
    EXPECT_LT(unweighted->slope, 1.9);
    EXPECT_FALSE(unweighted->weighted);
    EXPECT_GT(unweighted->slope_standard_error, 0) << "the scatter about the line gives the error";
    // One point without an error bar: no weights at all.
    EXPECT_FALSE(log_log_fit(h, e, 3, {1e-5, 2.5e-6, 0, 0.0005}, FitWeights::error_bars)->weighted);
    // The ordinary fit with error bars: the same line as without, its error from the bars.
    const auto ordinary = log_log_fit(h, e, 3, precise_but_last);
    EXPECT_DOUBLE_EQ(ordinary->slope, unweighted->slope);
    EXPECT_NE(ordinary->slope_standard_error, unweighted->slope_standard_error);
}

TEST(Statistics, MeanAndStandardError) {
    const auto m = mean_and_error({1, 2, 3, 4});
    EXPECT_DOUBLE_EQ(m.mean, 2.5);
    EXPECT_NEAR(m.standard_error, std::sqrt(5.0 / 3.0 / 4.0), 1e-15);
    EXPECT_EQ(m.count, 4u);
}

TEST(Statistics, ZScoreCombinesErrorBars) {
    EXPECT_DOUBLE_EQ(z_score({1.0, 0.3, 3}, {2.0, 0.4, 3}), 2.0);
    EXPECT_EQ(z_score({1.0, 0, 3}, {1.0, 0, 3}), 0.0);
    EXPECT_TRUE(std::isinf(z_score({1.0, 0, 3}, {2.0, 0, 3})));
}

TEST(Statistics, KolmogorovSmirnovTellsSameFromDifferentDistributions) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> a(0, 1), shifted(0.5, 1);
    std::vector<double> x, y, z;
    for (int i = 0; i < 2000; ++i) x.push_back(a(rng)), y.push_back(a(rng)), z.push_back(shifted(rng));
    EXPECT_GT(ks_two_sample(x, y).p_value, 1e-3);
    EXPECT_LT(ks_two_sample(x, z).p_value, 1e-6);
    EXPECT_NEAR(ks_two_sample({1, 2, 3}, {1, 2, 3}).statistic, 0.0, 0);
    EXPECT_NEAR(ks_two_sample({1, 2}, {3, 4}).statistic, 1.0, 0);
}

}  // namespace
}  // namespace collide::validation

namespace collide::validation {
namespace {

// A backend that offers both precisions ("float|double", e.g. opencl) is validated in its
// default, first-listed precision, so it gets the float tolerances; a pure double backend
// keeps the rounding-level ones.
TEST(DefaultTolerances, DualPrecisionBackendIsJudgedAsItsDefaultFloat) {
    const Tolerances dual = default_tolerances(find_backend("opencl"));
    const Tolerances single = default_tolerances(find_backend("cpu"));
    const Tolerances twice = default_tolerances(find_backend("step"));
    EXPECT_EQ(dual.momentum_drift, single.momentum_drift);
    EXPECT_LT(twice.momentum_drift, dual.momentum_drift);
}

// A solver that declares no rule (an outside engine) does not promise the stepped rules'
// "overlap removed in the step that finds it": it keeps a contact solver's 1e-2 beyond one step
// (planck as shipped leaves 1.7e-3 of slop, which the rules' rounding limit failed), while a
// declared rule keeps the rounding of its positions.
TEST(DefaultTolerances, AnUndeclaredSolverIsNotHeldToTheRulesOverlapRounding) {
    BackendInfo undeclared;
    undeclared.name = "engine";
    undeclared.precision = "double";
    BackendInfo rule = undeclared;
    rule.rule = "collide-first";
    RoundingScale scale;
    scale.smallest_radius = 0.5;
    scale.coordinate = 10;
    EXPECT_DOUBLE_EQ(default_tolerances(undeclared, scale).overlap_beyond_step, 1e-2);
    EXPECT_LT(default_tolerances(rule, scale).overlap_beyond_step, 1e-12);
}

}  // namespace
}  // namespace collide::validation
