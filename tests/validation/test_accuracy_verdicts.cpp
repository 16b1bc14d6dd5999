// What each backend can be used for, decided from its measured accuracy
// (validation/summary/accuracy_verdicts.h): use for / not for at the suite's stated accuracy,
// the scenes only checked, the scenes it cannot run, and a variant under its base's limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "validation/summary/accuracy_verdicts.h"

namespace collide::validation {
namespace {

CheckResult check(const std::string& backend, const std::string& scene, const std::string& name, double value,
                  double tolerance, CheckStatus status = CheckStatus::pass, const std::string& tail = "__dt0.004__seed1") {
    CheckResult c;
    std::string token = backend;
    std::replace(token.begin(), token.end(), '[', '-');
    token.erase(std::remove(token.begin(), token.end(), ']'), token.end());
    c.subject = scene + "__" + token + tail;
    c.scene = scene;
    c.backend = backend;
    c.check = name;
    c.status = status;
    c.value = value;
    c.tolerance = tolerance;
    return c;
}

WorkPrecisionPoint pressure_point(double dt, double relative, double se) {
    WorkPrecisionPoint p;
    p.dt = dt;
    p.error = std::fabs(relative);
    p.error_standard_error = se;
    p.replicates = 64;
    StatisticalDifference d;
    d.relative = relative;
    d.relative_standard_error = se;
    p.pressure = d;
    return p;
}

WorkPrecisionLine pressure_line(const std::string& backend, std::vector<WorkPrecisionPoint> points) {
    WorkPrecisionLine line;
    line.scene = "gas";
    line.backend = backend;
    line.error_kind = "|Z - Z_ref| / Z_ref";
    line.points = std::move(points);
    return line;
}

TEST(AccuracyVerdicts, NotForNamesTheSignedBiasAndItsStandardError) {
    // Z within 0.5 %: dt 0.002 (0.1 % +- 0.1 %) is; dt 0.004 (+0.8 % +- 0.2 %) and dt 0.006
    // (+1.15 % +- 0.22 %) are not, the latter the worst, resolved (1.15 - 1.96 * 0.22 > 0.5).
    const std::vector<CheckResult> checks = {check("step", "gas", "run", 0, 0)};
    const auto v = accuracy_verdicts("event", checks,
                                     {pressure_line("step", {pressure_point(0.006, 0.0115, 0.0022),
                                                             pressure_point(0.004, 0.008, 0.002),
                                                             pressure_point(0.002, 0.001, 0.001)})},
                                     VerdictThresholds{})
                       .at("step");
    ASSERT_EQ(v.use_for.size(), 1u);
    EXPECT_DOUBLE_EQ(v.use_for[0].dt, 0.002);
    ASSERT_EQ(v.not_for.size(), 1u);
    EXPECT_DOUBLE_EQ(v.not_for[0].dt_min, 0.004);
    EXPECT_DOUBLE_EQ(v.not_for[0].dt_max, 0.006);
    EXPECT_DOUBLE_EQ(v.not_for[0].error, 0.0115);
    EXPECT_NEAR(v.not_for[0].sigmas, 0.0115 / 0.0022, 1e-12);
    EXPECT_TRUE(v.not_for[0].resolved);
    EXPECT_TRUE(v.checked_only.empty());
}

TEST(AccuracyVerdicts, ANegativeBiasKeepsItsSignAndAnUnresolvedOneIsSaidToBe) {
    const auto v = accuracy_verdicts("event", {check("cpu", "gas", "run", 0, 0)},
                                     {pressure_line("cpu", {pressure_point(0.002, -0.004, 0.003)})}, VerdictThresholds{})
                       .at("cpu");
    ASSERT_EQ(v.not_for.size(), 1u);  // 0.4 % + 1.96 * 0.3 % > 0.5 %: not shown within
    EXPECT_DOUBLE_EQ(v.not_for[0].error, -0.004);
    EXPECT_FALSE(v.not_for[0].resolved);
    EXPECT_TRUE(v.use_for.empty());
    VerdictThresholds looser;
    looser.pressure_accuracy = 0.02;
    EXPECT_EQ(accuracy_verdicts("event", {check("cpu", "gas", "run", 0, 0)},
                                {pressure_line("cpu", {pressure_point(0.002, -0.004, 0.003)})}, looser)
                  .at("cpu").use_for.size(), 1u);
}

TEST(AccuracyVerdicts, ScenesWithoutAnErrorAreCheckedOnlyAndDeclinedOnesCannotRun) {
    const std::vector<CheckResult> checks = {check("event", "stones", "run", 0, 0),
                                             check("event", "periodic", "run", 0, 0, CheckStatus::left_out)};
    const auto v = accuracy_verdicts("event", checks, {}, VerdictThresholds{}).at("event");
    EXPECT_EQ(v.checked_only, std::vector<std::string>{"stones"});
    EXPECT_EQ(v.cannot_run, std::vector<std::string>{"periodic"});
    EXPECT_FALSE(v.under_preset_limits);
}

TEST(AccuracyVerdicts, AVariantIsJudgedAgainUnderItsBasesLimits) {
    // The shipped preset loses 90 % of the energy, within its own 0.95 but not the tuned 1e-3;
    // its trajectory error (0.5) within the tuned 4; a check the base leaves out is not compared.
    const std::vector<CheckResult> checks = {
        check("box2d", "pair", "energy_drift", 1e-5, 1e-3), check("box2d", "pair", "trajectory_error", 0.01, 4),
        check("box2d", "pair", "momentum_drift", 0, 0, CheckStatus::left_out),
        check("box2d[shipped]", "pair", "energy_drift", 0.909, 0.95),
        check("box2d[shipped]", "pair", "trajectory_error", 0.5, 4),
        check("box2d[shipped]", "pair", "momentum_drift", 0.3, 0, CheckStatus::left_out),
        check("box2d[shipped]", "pair", "energy_drift", 0.5, 0.95, CheckStatus::pass, "__dt0.004__seed9")};  // no twin
    const auto v = accuracy_verdicts("event", checks, {}, VerdictThresholds{});
    ASSERT_TRUE(v.at("box2d[shipped]").under_preset_limits);
    const UnderPresetLimits& u = *v.at("box2d[shipped]").under_preset_limits;
    EXPECT_EQ(u.preset, "box2d");
    EXPECT_EQ(u.compared, 2u);
    EXPECT_EQ(u.failing, 1u);
    EXPECT_EQ(u.failing_by_check.at("energy_drift"), 1u);
    EXPECT_FALSE(v.at("box2d").under_preset_limits) << "a base backend has no preset above it";
}

TEST(AccuracyVerdicts, CostAtTheStatedAccuracyIsInterpolatedOrNotReached) {
    // Error 0.02 at cost 1, 0.005 at cost 4 (dt halving twice): 0.01 lies halfway in log error,
    // so its cost is 2, between the two points' 1 and 4.
    WorkPrecisionLine line;
    line.scene = "pair";
    line.backend = "step";
    line.error_kind = "trajectory error / r_min";
    const std::tuple<double, double, double> points[] = {{0.004, 0.02, 1.0}, {0.001, 0.005, 4.0}};
    for (const auto& [dt, error, cost] : points) {
        WorkPrecisionPoint p;
        p.dt = dt, p.error = error, p.seconds_per_time_unit = cost, p.replicates = 2;
        line.points.push_back(p);
    }
    const std::vector<CheckResult> checks = {check("step", "pair", "run", 0, 0)};
    const auto v = accuracy_verdicts("event", checks, {line}, VerdictThresholds{}).at("step");
    ASSERT_EQ(v.cost_at_accuracy.size(), 1u);
    const CostAtAccuracy& c = v.cost_at_accuracy[0];
    EXPECT_TRUE(c.reached);
    EXPECT_FALSE(c.at_most);
    EXPECT_NEAR(c.seconds_per_time_unit, 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(c.low, 1.0);
    EXPECT_DOUBLE_EQ(c.high, 4.0);
    VerdictThresholds strict;
    strict.trajectory_accuracy = 1e-3;
    EXPECT_FALSE(accuracy_verdicts("event", checks, {line}, strict).at("step").cost_at_accuracy[0].reached);
    VerdictThresholds loose;
    loose.trajectory_accuracy = 0.05;
    const CostAtAccuracy l = accuracy_verdicts("event", checks, {line}, loose).at("step").cost_at_accuracy[0];
    EXPECT_TRUE(l.at_most);
    EXPECT_DOUBLE_EQ(l.seconds_per_time_unit, 1.0);
}

// A Z point whose pressure check could detect a bias of `detectable` (relative to Z_ref).
WorkPrecisionPoint z_point(const std::string& backend, double dt, double detectable, std::size_t replicates) {
    WorkPrecisionPoint p = pressure_point(dt, 0.001, 0.001);
    p.group = "gas__" + backend + "__dt" + std::to_string(dt);
    p.pressure->detectable = detectable;
    p.pressure->replicates = replicates;
    return p;
}

TEST(AccuracyVerdicts, ALowPowerPassIsListedWithTheSmallestBiasItCouldDetect) {
    // Z within 0.5 %: the passes at dt 0.004 (could detect 1.2 %, 4 replicates) and dt 0.002
    // (0.6 %, 16) could not have seen a bias of 0.5 %; the pass at dt 0.001 (0.3 %) could, the
    // failed check at dt 0.008 (2 %) is no pass and the left-out one at dt 0.016 no check.
    const std::vector<WorkPrecisionPoint> points = {z_point("step", 0.016, 0.03, 4), z_point("step", 0.008, 0.02, 4),
                                                    z_point("step", 0.004, 0.012, 4), z_point("step", 0.002, 0.006, 16),
                                                    z_point("step", 0.001, 0.003, 64)};
    std::vector<CheckResult> checks = {check("step", "gas", "run", 0, 0)};
    const CheckStatus status[] = {CheckStatus::left_out, CheckStatus::fail, CheckStatus::pass, CheckStatus::pass,
                                  CheckStatus::pass};
    for (std::size_t k = 0; k < points.size(); ++k) {
        CheckResult c = check("step", "gas", "pressure", 0, 4, status[k]);
        c.subject = points[k].group;
        checks.push_back(c);
    }
    const auto v = accuracy_verdicts("event", checks, {pressure_line("step", points)}, VerdictThresholds{}).at("step");
    ASSERT_EQ(v.low_power.size(), 1u);
    const LowPowerPass& l = v.low_power[0];
    EXPECT_EQ(l.scene, "gas");
    EXPECT_EQ(l.check, "pressure");
    EXPECT_EQ(l.passes, 2u);
    EXPECT_DOUBLE_EQ(l.dt_min, 0.002);
    EXPECT_DOUBLE_EQ(l.dt_max, 0.004);
    EXPECT_DOUBLE_EQ(l.detectable, 0.006);
    EXPECT_EQ(l.replicates, 16u);
    VerdictThresholds loose;  // Z within 2 %: every pass could have seen it
    loose.pressure_accuracy = 0.02;
    EXPECT_TRUE(accuracy_verdicts("event", checks, {pressure_line("step", points)}, loose).at("step").low_power.empty());
    // A line judged by another error (no stated accuracy for it here) still holds its Z to Z's.
    WorkPrecisionLine other = pressure_line("step", points);
    other.error_kind = "some other statistic";
    const auto w = accuracy_verdicts("event", checks, {other}, VerdictThresholds{}).at("step");
    ASSERT_EQ(w.low_power.size(), 1u);
    EXPECT_DOUBLE_EQ(w.low_power[0].detectable, 0.006);
    EXPECT_TRUE(w.not_for.empty());
}

TEST(AccuracyVerdicts, StatedAccuracyFollowsTheErrorKind) {
    VerdictThresholds t;
    t.cooling_accuracy = 7e-3;
    t.collision_rate_accuracy = 9e-3;
    EXPECT_DOUBLE_EQ(*stated_accuracy("trajectory error / r_min", t), 1e-2);
    EXPECT_DOUBLE_EQ(*stated_accuracy("|Z - Z_ref| / Z_ref", t), 5e-3);
    EXPECT_DOUBLE_EQ(*stated_accuracy("|tau - tau_ref| / tau_ref", t), 7e-3);
    EXPECT_DOUBLE_EQ(*stated_accuracy("|nu - nu_ref| / nu_ref", t), 9e-3);
    EXPECT_FALSE(stated_accuracy("something else", t));
}

// A cooling gas compared seed by seed: the point's error is |tau difference|, the verdict
// states the signed paired difference (not Z's, which the point also carries) against the
// cooling accuracy.
WorkPrecisionPoint paired_point(double dt, double relative, double se) {
    WorkPrecisionPoint p = pressure_point(dt, 0.5, 0.001);  // a Z far off: not what is judged
    p.replicates = 8;
    StatisticalDifference d;
    d.paired = true;
    d.relative = relative;
    d.relative_standard_error = se;
    d.replicates = 8;
    p.paired = d;
    p.error = std::fabs(relative);
    p.error_standard_error = se;
    return p;
}

TEST(AccuracyVerdicts, ACoolingGasEarnsUseForAndNotForFromItsPairedCoolingTime) {
    WorkPrecisionLine line = pressure_line("step", {paired_point(0.004, -0.012, 0.002), paired_point(0.001, 0.001, 0.0006)});
    line.scene = "inelastic_gas";
    line.error_kind = "|tau - tau_ref| / tau_ref";
    const std::vector<CheckResult> checks = {check("step", "inelastic_gas", "run", 0, 0)};
    const AccuracyVerdict v = accuracy_verdicts("event", checks, {line}, VerdictThresholds{}).at("step");
    EXPECT_TRUE(v.checked_only.empty());
    ASSERT_EQ(v.use_for.size(), 1u);  // 0.1 % + 1.96 * 0.06 % within 0.5 %
    EXPECT_EQ(v.use_for[0].scene, "inelastic_gas");
    EXPECT_DOUBLE_EQ(v.use_for[0].dt, 0.001);
    ASSERT_EQ(v.not_for.size(), 1u);  // -1.2 % +- 0.2 %: beyond 0.5 % at 95 %
    EXPECT_DOUBLE_EQ(v.not_for[0].error, -0.012);
    EXPECT_EQ(v.not_for[0].replicates, 8u);
    EXPECT_TRUE(v.not_for[0].resolved);
    VerdictThresholds loose;
    loose.cooling_accuracy = 0.02;  // the cooling accuracy, not Z's, decides
    EXPECT_TRUE(accuracy_verdicts("event", checks, {line}, loose).at("step").not_for.empty());
}

TEST(AccuracyVerdicts, AFewSeedPairedErrorIsBoundedWithStudentsTNotTheNormal196) {
    // 0.2 % +- 0.1 % from 4 paired seeds: within 0.5 % by the normal bound (0.2 + 1.96 * 0.1 =
    // 0.396 %) but not by Student's t with 3 degrees of freedom (0.2 + 3.182 * 0.1 = 0.518 %):
    // the standard error comes from the scatter of 4 differences. With 8 seeds (t = 2.365:
    // 0.437 %) it is within.
    auto line_of = [](std::size_t seeds) {
        WorkPrecisionPoint p = paired_point(0.002, 0.002, 0.001);
        p.replicates = seeds;
        p.paired->replicates = seeds;
        WorkPrecisionLine line = pressure_line("step", {p});
        line.scene = "inelastic_gas";
        line.error_kind = "|tau - tau_ref| / tau_ref";
        return line;
    };
    const std::vector<CheckResult> checks = {check("step", "inelastic_gas", "run", 0, 0)};
    const AccuracyVerdict four = accuracy_verdicts("event", checks, {line_of(4)}, VerdictThresholds{}).at("step");
    EXPECT_TRUE(four.use_for.empty());
    ASSERT_EQ(four.not_for.size(), 1u);
    EXPECT_NEAR(four.not_for[0].confidence_factor, 3.182, 1e-3);
    EXPECT_FALSE(four.not_for[0].resolved);  // 0.2 % - 3.18 * 0.1 % is not beyond 0.5 %: undecided
    const AccuracyVerdict eight = accuracy_verdicts("event", checks, {line_of(8)}, VerdictThresholds{}).at("step");
    ASSERT_EQ(eight.use_for.size(), 1u);
    EXPECT_NEAR(eight.use_for[0].confidence_factor, 2.365, 1e-3);
}

TEST(AccuracyVerdicts, AnUnpairedErrorKeepsTheNormal196) {
    WorkPrecisionPoint p = paired_point(0.002, 0.002, 0.001);
    p.paired.reset();  // a Z error from many batches: the normal bound
    EXPECT_DOUBLE_EQ(confidence_factor(p), confidence_95);
}

TEST(AccuracyVerdicts, CheckedOnlyScenesSayWhy) {
    CheckResult refused = check("step", "far", "collision_rate", 0, 0, CheckStatus::left_out);
    refused.detail = "the reference backend cannot run this scene: gravity with stones";
    const std::vector<CheckResult> checks = {check("step", "far", "run", 0, 0), refused,
                                             check("step", "near", "run", 0, 0), check("event", "near", "run", 0, 0)};
    const auto v = accuracy_verdicts("event", checks, {}, VerdictThresholds{});
    EXPECT_EQ(v.at("step").checked_only, (std::vector<std::string>{"far", "near"}));
    EXPECT_EQ(v.at("step").checked_only_reasons.at("far"), refused.detail);
    EXPECT_NE(v.at("step").checked_only_reasons.at("near").find("no `compare` for this scene"), std::string::npos);
    EXPECT_NE(v.at("event").checked_only_reasons.at("near").find("the reference"), std::string::npos);
}

}  // namespace
}  // namespace collide::validation
