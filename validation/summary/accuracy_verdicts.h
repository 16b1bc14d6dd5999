// What each backend can be used for, decided from its measured accuracy (issue 48, item 2;
// docs/reading-a-report.md, "Choosing a backend for a stated accuracy"):
//
//  - use for: a scene and the largest dt at which its error against the reference is within the
//    suite's stated accuracy ([verdicts] trajectory_accuracy, pressure_accuracy, and for the
//    scenes compared seed by seed cooling_accuracy, collision_rate_accuracy) at 95 % confidence:
//    error + 1.96 SE <= accuracy (Student's t point for the replicates instead of 1.96 where the
//    error is a seed-paired mean that estimates its own standard error from few seeds);
//  - not for: a scene where some dt is not shown within it, with the measured error (the signed
//    pressure bias where there is one), its SE and how many SE it lies from zero; `resolved` where
//    even error - 1.96 SE exceeds the accuracy (else more replicates could still clear it);
//  - checked only: scenes it runs with no error against the reference (conservation, overlaps),
//    each with the reason: the detail of its comparison check left out (the reference cannot run
//    the scene, ...), else that the suite sets no `compare` for the scene;
//  - low-power passes: a scene whose statistical check of Z passed where it could not have
//    detected a bias as large as the stated accuracy (its detectable bias exceeds it): the pass
//    bounds the bias only by the detectable one, which the first screen states beside it;
//  - cannot run: scenes whose every `run` check is left out (the backend declined the scene);
//  - a variant (NAME[preset]) judged against its own tolerances: how many of its checks fail under
//    the limits of its base backend's tuned preset, by check.
// Decided here and written to summary.json (`verdicts.B.accuracy`); the report only words it.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "validation/plan/suite.h"
#include "validation/record/check_result.h"
#include "validation/record/comparisons.h"

namespace collide::validation {

// The accuracy a work-precision line's error is held to (its error_kind): none for a kind the
// suite states no accuracy for.
std::optional<double> stated_accuracy(const std::string& error_kind, const VerdictThresholds& thresholds);

struct UseFor {
    std::string scene, error_kind;
    double accuracy = 0;
    double dt = 0;  // the largest dt within the accuracy
    double error = 0, standard_error = 0;
    std::size_t replicates = 0;
    double confidence_factor = 0;  // the SE's factor in the 95 % bound: 1.96, or Student's t point
};

struct NotFor {
    std::string scene, error_kind;
    double accuracy = 0;
    double dt_min = 0, dt_max = 0;  // the dt range not shown within the accuracy
    double dt = 0;                  // the dt of the largest error in that range
    double error = 0;               // signed: the relative statistical difference where measured, else the error
    double standard_error = 0;
    double sigmas = 0;              // |error| / standard_error
    std::size_t replicates = 0;
    bool resolved = false;          // |error| - factor SE > accuracy: beyond it at 95 % confidence
    double confidence_factor = 0;   // as UseFor's
};

// What a backend's work-precision line costs at the stated accuracy: wall seconds per simulated
// time unit where its mean error crosses the accuracy, interpolated linearly in log cost against
// log error between the two points that bracket it; `low`..`high` the costs of those two points
// (the interpolation's uncertainty). `at_most`: the coarsest point is already within, so the
// accuracy costs at most its cost. Not reached: no point's error is within the accuracy.
struct CostAtAccuracy {
    std::string scene, error_kind;
    double accuracy = 0;
    bool reached = false, at_most = false;
    double seconds_per_time_unit = 0, low = 0, high = 0;
};

// A scene's passing `pressure` checks that could not have failed on a bias as large as the stated
// Z accuracy: each point's detectable bias (StatisticalDifference::detectable: the check's z
// limit times the combined standard error over |Z_ref|, the bias it fails with probability about
// one half) exceeds the accuracy. Such a pass says the bias is probably below `detectable`, not
// below the accuracy; more replicates shrink `detectable` as 1/sqrt(replicates). `detectable`
// and `replicates` are the most sensitive of these points' (the smallest detectable bias), so
// "could only detect a bias >= detectable" holds for every one of them.
struct LowPowerPass {
    std::string scene, check;
    double accuracy = 0;
    double dt_min = 0, dt_max = 0;  // the dt range of these passes
    double detectable = 0;
    std::size_t replicates = 0;
    std::size_t passes = 0;  // how many sweep points passed with low power
};

// A variant's checks judged again under its base backend's limits (same scene, check and case).
struct UnderPresetLimits {
    std::string preset;            // the base backend whose limits were applied
    std::size_t compared = 0, failing = 0;
    std::map<std::string, std::size_t> failing_by_check;
};

struct AccuracyVerdict {
    std::vector<UseFor> use_for;
    std::vector<NotFor> not_for;
    std::vector<CostAtAccuracy> cost_at_accuracy;
    std::vector<LowPowerPass> low_power;
    std::vector<std::string> checked_only, cannot_run;
    std::map<std::string, std::string> checked_only_reasons;  // by scene of checked_only
    std::optional<UnderPresetLimits> under_preset_limits;
};

std::map<std::string, AccuracyVerdict> accuracy_verdicts(const std::string& reference,
                                                         const std::vector<CheckResult>& checks,
                                                         const std::vector<WorkPrecisionLine>& lines,
                                                         const VerdictThresholds& thresholds);

// 1.96: the two-sided 95 % point of the normal distribution.
constexpr double confidence_95 = 1.96;

// The factor of a work-precision point's standard error in its 95 % bound: Student's t point
// with n - 1 degrees of freedom for a difference paired over n seeds (its standard error comes
// from the scatter of those n differences: with 4 seeds the bound is 3.18 SE, not 1.96), else
// confidence_95 (an error from many batches or replicates).
double confidence_factor(const WorkPrecisionPoint& p);

}  // namespace collide::validation
