// Batch means, the integrated autocorrelation time and the equilibration cut on series whose
// answers are known analytically: white noise (tau_int = 1/2) and an AR(1) process
// x_{t+1} = a x_t + noise, whose tau_int = (1 + a) / (2 (1 - a)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>

#include "core/statistics/batch_means.h"

namespace collide {
namespace {

std::vector<double> ar1(double a, std::size_t n, unsigned seed, double offset = 0) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0, 1);
    std::vector<double> x(n);
    double v = 0;
    for (auto& xi : x) xi = offset + (v = a * v + noise(rng));
    return x;
}

TEST(BatchMeans, WhiteNoiseHasHalfAnEntryOfCorrelation) {
    const auto x = ar1(0, 200000, 1);
    EXPECT_NEAR(integrated_autocorrelation_time(x), 0.5, 0.03);
}

TEST(BatchMeans, Ar1CorrelationTimeIsAnalytic) {
    const double a = 0.9;  // tau_int = 1.9 / 0.2 = 9.5
    EXPECT_NEAR(integrated_autocorrelation_time(ar1(a, 400000, 2)), 9.5, 0.6);
}

TEST(BatchMeans, ErrorBarCoversTheTrueMeanAtTheStatedRate) {
    // Over 200 independent AR(1) series the true mean 0 lies within 2 error bars in about 95 %.
    int inside = 0;
    for (unsigned s = 0; s < 200; ++s) {
        const SeriesEstimate e = estimate_stationary_mean(ar1(0.8, 4000, 100 + s), false);
        inside += std::abs(e.mean) < 2 * e.error;
    }
    EXPECT_GT(inside, 170);  // 95 % of 200 = 190; batch means with 20 batches runs a little low
    EXPECT_LT(inside, 200);
}

TEST(BatchMeans, EquilibrationCutLeavesOutAnInitialDrift) {
    auto x = ar1(0.5, 10000, 3);
    for (std::size_t i = 0; i < 1500; ++i) x[i] += 20.0 * (1500 - double(i)) / 1500;  // a melt
    const SeriesEstimate e = estimate_stationary_mean(x);
    EXPECT_GE(e.equilibration_cut, 1000u);
    EXPECT_NEAR(e.mean, 0, 5 * e.error);
    const SeriesEstimate whole = estimate_stationary_mean(x, false);
    EXPECT_GT(std::abs(whole.mean), 5 * e.error);  // without the cut the drift biases it
}

// The candidates behind the cut: starts 0, n/20, ... n/2, each with (n - t0) / (2 tau_int(t0)),
// and the cut the estimate takes is the first with the most; the melt makes the early ones few.
TEST(BatchMeans, TheCutIsTheCandidateWithTheMostEffectiveSamples) {
    auto x = ar1(0.5, 10000, 3);
    for (std::size_t i = 0; i < 1500; ++i) x[i] += 20.0 * (1500 - double(i)) / 1500;
    const std::vector<CutCandidate> candidates = equilibration_candidates(x);
    ASSERT_EQ(candidates.size(), 11u);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        EXPECT_EQ(candidates[k].cut, 500 * k);
        const std::vector<double> rest(x.begin() + std::ptrdiff_t(500 * k), x.end());
        EXPECT_DOUBLE_EQ(candidates[k].effective_samples,
                         double(rest.size()) / std::max(1.0, 2 * integrated_autocorrelation_time(rest)));
    }
    const auto best = std::max_element(candidates.begin(), candidates.end(),
                                       [](const CutCandidate& a, const CutCandidate& b) { return a.effective_samples < b.effective_samples; });
    EXPECT_EQ(estimate_stationary_mean(x).equilibration_cut, best->cut);
    EXPECT_LT(candidates[0].effective_samples, 0.5 * best->effective_samples);
}

}  // namespace
}  // namespace collide
