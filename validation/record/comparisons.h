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
    double upper_limit_95 = 0;         // |relative| + 1.96 relative_standard_error
    // The smallest |relative difference - prediction| the check fails (power about one half):
    // its z limit times the combined standard error (with the prediction's uncertainty), / |reference|.
    double detectable = 0;
    double predicted = std::numeric_limits<double>::quiet_NaN();  // the stepped rule's absolute shift
    double predicted_uncertainty = std::numeric_limits<double>::quiet_NaN();
    std::size_t replicates = 0, reference_replicates = 0;
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
};

struct WorkPrecisionLine {
    std::string scene, backend;
    std::string error_kind;            // "trajectory error / r_min" or "|Z - Z_ref| / Z_ref"
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
