// The observed order on the asymptotic range (validation/compare/convergence_order.h) and the joint
// fit of the stepped rules' bias constants (validation/models/bias_fit.h), on synthetic lines whose
// answer is known.
#include <gtest/gtest.h>

#include <cmath>

#include "validation/models/bias_fit.h"
#include "validation/compare/convergence_order.h"
#include "validation/models/statistics_bias_model.h"

namespace collide::validation {
namespace {

TEST(ConvergenceOrder, AStraightFirstOrderLineHasOrderOneOnEveryPoint) {
    std::vector<ErrorPoint> points;
    for (double h : {4e-3, 2e-3, 1e-3, 5e-4}) points.push_back({h, 0.7 * h, 0.01 * h});
    const auto o = asymptotic_order(points);
    ASSERT_TRUE(o.order);
    EXPECT_NEAR(*o.order, 1.0, 1e-9);
    EXPECT_EQ(o.used, 4u);
    EXPECT_FALSE(o.floor);
    EXPECT_FALSE(o.bending);
    EXPECT_DOUBLE_EQ(o.h_coarse, 4e-3);
    EXPECT_DOUBLE_EQ(o.h_fine, 5e-4);
}

TEST(ConvergenceOrder, AFloorIsCutOffAndTheOrderFittedAboveIt) {
    // Second order down to h = 1e-3, then the error rises (rounding accumulates).
    std::vector<ErrorPoint> points{{8e-3, 64e-6, 0}, {4e-3, 16e-6, 0}, {2e-3, 4e-6, 0}, {1e-3, 1e-6, 0},
                                   {5e-4, 1.5e-6, 0}, {2.5e-4, 2.5e-6, 0}};
    const auto o = asymptotic_order(points);
    ASSERT_TRUE(o.order);
    EXPECT_NEAR(*o.order, 2.0, 1e-9);
    ASSERT_TRUE(o.floor);
    EXPECT_DOUBLE_EQ(o.floor->h, 1e-3);
    EXPECT_EQ(o.floor->excluded, 2u);
    EXPECT_DOUBLE_EQ(o.floor->finest_error, 2.5e-6);
    EXPECT_DOUBLE_EQ(o.h_fine, 1e-3);
}

TEST(ConvergenceOrder, AStallInsideTheRangeIsFlaggedNotCalledAsymptotic) {
    // Local orders 1.3, 0.15, 0.6 (cpu on `glancing`): the error stalls, then falls again.
    const double h[] = {4e-3, 2e-3, 1e-3, 5e-4};
    double e = 1e-3;
    std::vector<ErrorPoint> points{{h[0], e, 0}};
    for (double local : {1.3, 0.15, 0.6}) {
        e /= std::pow(2.0, local);
        points.push_back({h[points.size()], e, 0});
    }
    const auto o = asymptotic_order(points);
    ASSERT_TRUE(o.order);
    EXPECT_FALSE(o.floor);
    EXPECT_EQ(o.used, 4u);
    EXPECT_TRUE(o.bending);
}

TEST(ConvergenceOrder, NoisyStatisticalPointsAreNoFloor) {
    // Z's difference at three close steps: the finest lies higher, but within its error bar.
    std::vector<ErrorPoint> points{{6e-3, 0.0115, 0.002}, {4.8e-3, 0.0090, 0.002}, {4e-3, 0.0095, 0.002}};
    const auto o = asymptotic_order(points);
    EXPECT_FALSE(o.floor);
    EXPECT_EQ(o.used, 3u);
    ASSERT_TRUE(o.order);
    ASSERT_TRUE(o.standard_error);
    EXPECT_GT(*o.standard_error, 0.5);  // three points over 1.5x in h pin nothing
}

TEST(ConvergenceOrder, TooFewPointsGiveANoteAndNoOrder) {
    const auto o = asymptotic_order({{2e-3, 0.01, 0}, {1e-3, 0.005, 0}, {5e-4, 0, 0}});
    EXPECT_FALSE(o.order);
    EXPECT_EQ(o.points, 2u);
    EXPECT_NE(o.note.find("needs 3"), std::string::npos);
}

StatisticalDifference measured(double difference, double se, double predicted) {
    StatisticalDifference d;
    d.reference = 2.0;
    d.mean = 2.0 + difference;
    d.standard_error = se;
    d.reference_standard_error = 0;
    d.predicted = predicted;
    return d;
}

TEST(BiasFit, RecoversTheConstantOfPointsThatAllLieBelowThePrediction) {
    const double model = fitted_statistics_bias().pressure;
    WorkPrecisionLine line;
    line.backend = "step";
    // Predictions for c = model; measured differences are 0.8 of them, each with SE 0.001.
    for (double p : {0.02, 0.016, 0.013}) {
        WorkPrecisionPoint point;
        point.pressure = measured(0.8 * p, 0.001, p);
        line.points.push_back(point);
    }
    const auto fits = fit_bias_constants({line});
    ASSERT_EQ(fits.size(), 1u);
    EXPECT_EQ(fits[0].observable, "pressure");
    EXPECT_NEAR(fits[0].constant, 0.8 * model, 1e-9);
    EXPECT_NEAR(fits[0].chi2, 0, 1e-9);
    EXPECT_GT(fits[0].chi2_model, 10);  // the model's constant misses all three
    EXPECT_EQ(fits[0].points, 3u);
    EXPECT_DOUBLE_EQ(fits[0].model, model);
}

TEST(BiasFit, PointsWithoutAPredictionAreNotFitted) {
    WorkPrecisionLine line;
    line.backend = "event";
    for (int k = 0; k < 3; ++k) {
        WorkPrecisionPoint point;
        point.pressure = measured(0.001, 0.001, std::nan(""));
        line.points.push_back(point);
    }
    EXPECT_TRUE(fit_bias_constants({line}).empty());
}

}  // namespace
}  // namespace collide::validation
