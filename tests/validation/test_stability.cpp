// Stability classification: the outcomes' precedence on synthetic case results (each result
// broken in several ways at once must report the most severe), and tunnelling detection on a
// synthetic pair that passes through its partner against one that bounces.
#include <gtest/gtest.h>

#include "validation/judge/stability.h"
#include "validation/judge/tunnelling.h"

namespace collide::validation {
namespace {

// Two disks (radius 0.5) on the x axis at output times 0, 1, 2, 3; disk 1 at rest at x = 5,
// disk 0 at x_0[k] (and y = 2 + offset).
CaseResult pair_run(std::vector<double> x0, double offset = 0) {
    CaseResult r;
    for (std::size_t k = 0; k < x0.size(); ++k) {
        r.trajectory_time.push_back(double(k));
        r.trajectory.push_back(Snapshot{{x0[k], 5.0}, {2.0 + offset, 2.0}, {0, 0}, {0, 0}, {0.5, 0.5}});
        Metrics m;
        m.time = double(k);
        m.kinetic_energy = 1.0;
        r.series.push_back(m);
    }
    return r;
}

const CaseResult kBounce = pair_run({1.0, 3.0, 2.0, 1.0});      // the exact run: back off after contact
const CaseResult kPassThrough = pair_run({1.0, 3.0, 7.0, 9.0}); // straight through disk 1

SceneFeatures walls() {
    SceneFeatures f;
    f.reflecting_walls = true;
    return f;
}

TEST(Tunnelling, APairThatPassesThroughIsCountedOneThatBouncesIsNot) {
    const auto through = count_tunnelling(kPassThrough, kBounce, false);
    ASSERT_TRUE(through.evaluated);
    EXPECT_EQ(through.pairs, 1u);
    EXPECT_NE(through.first.find("t = 2"), std::string::npos) << through.first;
    EXPECT_EQ(count_tunnelling(kBounce, kBounce, false).pairs, 0u);
}

TEST(Tunnelling, PassingBesideOrWhereTheReferenceAlsoCrossesIsNoTunnelling) {
    // 1.5 apart sideways (> contact distance 1): the disks miss each other.
    EXPECT_EQ(count_tunnelling(pair_run({1.0, 3.0, 7.0, 9.0}, 1.5), kBounce, false).pairs, 0u);
    // The reference has them crossed too (a legitimate pass, e.g. after a deflection).
    EXPECT_EQ(count_tunnelling(kPassThrough, kPassThrough, false).pairs, 0u);
    // Periodic boxes: not evaluated, and said so.
    const auto periodic = count_tunnelling(kPassThrough, kBounce, true);
    EXPECT_FALSE(periodic.evaluated);
    EXPECT_FALSE(periodic.not_evaluated.empty());
}

TEST(Stability, OutcomesFollowTheirPrecedence) {
    Tolerances tol;
    tol.max_overlap = 0.2;
    tol.energy_drift = 0.02;
    // Every fault at once, then remove the most severe one at a time.
    CaseResult r = kPassThrough;
    r.series[2].max_overlap = 0.9;
    r.series[3].kinetic_energy = 2.0;
    r.series[3].nonfinite = 1;
    r.status = RunStatus::crashed;
    EXPECT_EQ(classify(r, &kBounce, walls(), tol).outcome, Outcome::crash);
    r.status = RunStatus::timed_out;
    EXPECT_EQ(classify(r, &kBounce, walls(), tol).outcome, Outcome::hang);
    r.status = RunStatus::error;
    r.diagnostic = "step: 1 disk(s) with NaN/Inf state at t = 3";
    EXPECT_EQ(classify(r, &kBounce, walls(), tol).outcome, Outcome::nan);
    r.diagnostic = "solver gave up";
    r.series[3].nonfinite = 0;
    EXPECT_EQ(classify(r, &kBounce, walls(), tol).outcome, Outcome::crash) << "a solver that throws is a crash";
    r.status = RunStatus::completed;
    EXPECT_EQ(classify(r, &kBounce, walls(), tol).outcome, Outcome::tunnelling);
    EXPECT_EQ(classify(r, nullptr, walls(), tol).outcome, Outcome::excessive_overlap)
        << "without a reference, tunnelling cannot be judged";
    r.series[2].max_overlap = 0.1;
    EXPECT_EQ(classify(r, nullptr, walls(), tol).outcome, Outcome::energy_growth);
    r.series[3].kinetic_energy = 1.01;
    const auto stable = classify(r, nullptr, walls(), tol);
    EXPECT_EQ(stable.outcome, Outcome::stable);
    EXPECT_NE(stable.reason.find("tunnelling not evaluated"), std::string::npos) << stable.reason;
}

TEST(Stability, EnergyGrowthOnlyWherePhysicsForbidsIt) {
    Tolerances tol;
    CaseResult r = kBounce;
    r.series[2].kinetic_energy = 1.5;
    EXPECT_EQ(classify(r, nullptr, walls(), tol).outcome, Outcome::energy_growth);
    SceneFeatures pushed = walls();
    pushed.moving_stones = true;  // a moving stone does work on the disks
    EXPECT_EQ(classify(r, nullptr, pushed, tol).outcome, Outcome::stable);
    // Under gravity the total energy counts: kinetic energy may rise as a disk falls.
    SceneFeatures falling = walls();
    falling.gravity = true;
    r.series[2].potential_energy = -0.5;  // total energy 1.0: it did not rise
    EXPECT_EQ(classify(r, nullptr, falling, tol).outcome, Outcome::stable);
    EXPECT_DOUBLE_EQ(energy_growth(r.series, false), 0.5);
}

TEST(Stability, LeftOutCasesAreNotClassifiedAsFailures) {
    CaseResult r;
    r.status = RunStatus::left_out;
    EXPECT_EQ(classify(r, nullptr, walls(), Tolerances{}).outcome, Outcome::left_out);
}

// Three disks of radius 0.5 that start at x = 0, 10, 20 and end shifted by `moved` along x.
CaseResult moved_by(double moved) {
    CaseResult r;
    r.initial = Snapshot{{0.0, 10.0, 20.0}, {1.0, 1.0, 1.0}, {1, 1, 1}, {0, 0, 0}, {0.5, 0.5, 0.5}};
    r.final_state = r.initial;
    for (double& x : r.final_state.x) x += moved;
    r.series.resize(2);
    r.series[0].kinetic_energy = r.series[1].kinetic_energy = 1.0;
    r.series[1].time = 1.0;
    return r;
}

TEST(Stability, StalledWhenTheDisksBarelyMoveWhereTheReferenceMovesThem) {
    Tolerances tol;
    tol.max_overlap = 0.2;
    tol.energy_drift = 0.02;
    const CaseResult reference = moved_by(1.0);
    EXPECT_DOUBLE_EQ(median_displacement(reference), 1.0);
    const Classification frozen = classify(moved_by(0.0), &reference, walls(), tol);
    EXPECT_EQ(frozen.outcome, Outcome::stalled);
    EXPECT_NE(frozen.reason.find("median displacement 0"), std::string::npos) << frozen.reason;
    // A tenth of the reference's motion is the limit: below it stalled, above it not.
    EXPECT_EQ(classify(moved_by(0.09), &reference, walls(), tol).outcome, Outcome::stalled);
    EXPECT_EQ(classify(moved_by(0.11), &reference, walls(), tol).outcome, Outcome::stable);
    // Nothing to judge when the reference itself stays put (a packing at rest) or is missing.
    const CaseResult at_rest = moved_by(0.0);
    EXPECT_EQ(classify(moved_by(0.0), &at_rest, walls(), tol).outcome, Outcome::stable);
    EXPECT_EQ(classify(moved_by(0.0), nullptr, walls(), tol).outcome, Outcome::stable);
    // NaN is more severe than a stall.
    CaseResult broken = moved_by(0.0);
    broken.series[1].nonfinite = 1;
    EXPECT_EQ(classify(broken, &reference, walls(), tol).outcome, Outcome::nan);
}

// A stability suite maps failures: a stepped backend breaking is a finding; the exact solver
// breaking, a crash, or a case left unclassified is not (validate exits 1 only for those).
TEST(Stability, OnlyTheReferenceFailingACrashOrAnUnclassifiedCaseIsUnexpected) {
    CaseResult stepped, exact;
    stepped.spec.id = "s__step__dt0.01__seed1";
    exact.spec.id = "s__event__seed1";
    exact.spec.reference = true;
    const Classification stable{Outcome::stable, ""}, tunnelled{Outcome::tunnelling, "1 pair"},
        hang{Outcome::hang, "time limit"}, crash{Outcome::crash, "signal 6"};
    EXPECT_TRUE(unexpected_outcomes({stepped, exact}, {tunnelled, stable}).empty());
    EXPECT_TRUE(unexpected_outcomes({stepped, exact}, {hang, stable}).empty());
    const auto crashed = unexpected_outcomes({stepped, exact}, {crash, stable});
    ASSERT_EQ(crashed.size(), 1u);
    EXPECT_NE(crashed[0].find("s__step__dt0.01__seed1: crash"), std::string::npos);
    const auto exact_failed = unexpected_outcomes({stepped, exact}, {stable, hang});
    ASSERT_EQ(exact_failed.size(), 1u);
    EXPECT_NE(exact_failed[0].find("reference backend is not stable: hang"), std::string::npos);
    EXPECT_EQ(unexpected_outcomes({stepped, exact}, {stable}).size(), 1u);  // one case not classified
}

}  // namespace
}  // namespace collide::validation
