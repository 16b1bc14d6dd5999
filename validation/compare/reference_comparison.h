// Comparisons of every backend with the reference backend (event): trajectory error on
// few-body scenes, statistical observables with replicate error bars on many-body scenes,
// and the work-precision data (run time against error over the dt / substeps sweep).
#pragma once

#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "validation/judge/checks.h"
#include "validation/compare/convergence_order.h"
#include "validation/compare/predictability_horizon.h"
#include "validation/plan/suite.h"

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

// `tolerances` maps a backend name to its tolerances and `declared` to what it declares (a
// stepping rule's statistics are held to the rule's predicted bias; an exact solver in double has
// its trajectory held to the rounding level of the reference's twins); `features` is parallel to
// suite.scenes.
Comparisons compare_with_reference(const Suite& suite, const std::vector<CaseResult>& results,
                                   const std::vector<SceneFeatures>& features,
                                   const std::map<std::string, Tolerances>& tolerances,
                                   const std::map<std::string, const BackendInfo*>& declared);
// The smallest radius of a snapshot's disks: trajectory errors are measured in it.
double smallest_radius(const Snapshot& s);

// The largest distance between a disk of `a` and the same disk of `b`, / r_min (NaN when the
// snapshots hold different numbers of disks or a position is not finite).
double snapshot_separation(const Snapshot& a, const Snapshot& b, double r_min);

// snapshot_separation at every common output time, in the reference's r_min; empty when the
// trajectories cannot be compared (not recorded, other output times).
std::vector<double> trajectory_error_series(const CaseResult& a, const CaseResult& reference);

// max over common output times and disks of the (minimum-image) distance between two
// trajectories, divided by the smallest radius; NaN when they cannot be compared.
double trajectory_error(const CaseResult& a, const CaseResult& reference, const Scene* scene = nullptr);

}  // namespace collide::validation
