// The records of the comparison with the reference backend: the statistical differences, the
// work-precision lines and the checks and trajectory judgements it adds. Made by
// compare/reference_comparison.h; read by the runner, the bias fits and the summary.
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "validation/record/check_result.h"
#include "validation/record/observed_order.h"
#include "validation/record/trajectory_judgement.h"

namespace collide::validation {

// A statistical observable (Z, the collision rate) of one sweep group against the reference:
// the replicate means, their relative difference, and what the test can and cannot resolve.
struct StatisticalDifference {
    double mean = 0, standard_error = 0;                  // the group's replicate mean
    double reference = 0, reference_standard_error = 0;   // the reference's
    double relative = 0;               // (mean - reference) / reference, signed
    double relative_standard_error = 0;  // sqrt(se^2 + se_ref^2) / |reference|
    double sigmas = 0;                 // |mean - reference| / sqrt(se^2 + se_ref^2)
    bool resolved = false;             // sigmas >= resolved_standard_errors
    double upper_limit_95 = 0;         // |relative| + 1.96 relative_standard_error (paired over n seeds: Student's t point, n - 1 dof)
    // The smallest |relative difference - prediction| the check fails (power about one half):
    // its z limit times the combined standard error (with the prediction's uncertainty), / |reference|.
    double detectable = 0;
    double predicted = std::numeric_limits<double>::quiet_NaN();  // the stepped rule's absolute shift
    double predicted_uncertainty = std::numeric_limits<double>::quiet_NaN();
    std::size_t replicates = 0, reference_replicates = 0;
    // Paired by seed (compare/reference_comparison.cpp, "paired_difference"): each seed of the
    // backend started from the reference's configuration of that seed, so `relative` and its
    // standard error come from the per-seed differences (their mean `difference` and its SE),
    // not from the two means' scatters; replicates = reference_replicates = the pairs.
    bool paired = false;
    double difference = 0, difference_standard_error = 0;
};
constexpr double resolved_standard_errors = 2.0;

// One sweep point of one backend on one scene, averaged over its replicates.
struct WorkPrecisionPoint {
    std::string group;                 // group id (case id without the seed)
    double dt = 0;
    int substeps = 1;
    int iterations = 0;                // 0 = the backend's default
    double seconds_per_time_unit = 0;  // mean wall time per simulated time unit (after warm-up)
    double error = 0;                  // error vs the reference (see error_kind)
    double error_standard_error = 0;
    std::size_t replicates = 0;
    std::optional<StatisticalDifference> pressure, collision_rate;  // statistical scenes
    // The scene's own statistic, paired by seed, where the point's error is not Z (a cooling
    // gas: Haff's cooling time; a scene whose Z is left out: the collision rate). Its error kind
    // names it (paired_error_kind in reference_comparison.cpp).
    std::optional<StatisticalDifference> paired;
};

struct WorkPrecisionLine {
    std::string scene, backend;
    // "trajectory error / r_min", "|Z - Z_ref| / Z_ref", or a paired statistic's
    // "|tau - tau_ref| / tau_ref" (Haff cooling time) or "|nu - nu_ref| / nu_ref" (collision rate)
    std::string error_kind;
    std::vector<WorkPrecisionPoint> points;
    ConvergenceOrder order;            // on the asymptotic range (convergence_order.h)
};

struct Comparisons {
    std::vector<CheckResult> checks;
    std::vector<WorkPrecisionLine> work_precision;
    // Each trajectory case's error judged up to its reference's predictability horizon, by
    // case id (predictability_horizon.h): summary.json records them.
    std::map<std::string, TrajectoryJudgement> trajectories;
};

}  // namespace collide::validation
