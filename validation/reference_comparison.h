// Comparisons of every backend with the reference backend (event): trajectory error on
// few-body scenes, statistical observables with replicate error bars on many-body scenes,
// and the work-precision data (run time against error over the dt / substeps sweep).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "checks.h"
#include "suite.h"

namespace collide::validation {

// One sweep point of one backend on one scene, averaged over its replicates.
struct WorkPrecisionPoint {
    std::string group;                 // group id (case id without the seed)
    double dt = 0;
    int substeps = 1;
    int iterations = 0;                // 0 = the backend's default
    double seconds_per_time_unit = 0;  // mean wall time per simulated time unit (after warm-up)
    double error = 0;                  // mean error vs the reference (see error_kind)
    double error_standard_error = 0;
    std::size_t replicates = 0;
};

struct WorkPrecisionLine {
    std::string scene, backend;
    std::string error_kind;            // "trajectory error / r_min" or "|Z - Z_ref| / Z_ref"
    std::vector<WorkPrecisionPoint> points;
    std::optional<double> order;       // observed convergence order: slope of log error vs log dt
    std::optional<double> order_standard_error;  // its standard error (statistics.h, log_log_fit)
    std::string order_note;            // why the order is not defined, when it is not
};

struct Comparisons {
    std::vector<CheckResult> checks;
    std::vector<WorkPrecisionLine> work_precision;
};

// `tolerances` maps a backend name to its tolerances; `features` is parallel to suite.scenes.
Comparisons compare_with_reference(const Suite& suite, const std::vector<CaseResult>& results,
                                   const std::vector<SceneFeatures>& features,
                                   const std::map<std::string, Tolerances>& tolerances);

// max over common output times and disks of the (minimum-image) distance between two
// trajectories, divided by the smallest radius; NaN when they cannot be compared.
double trajectory_error(const CaseResult& a, const CaseResult& reference, const Scene* scene = nullptr);

}  // namespace collide::validation
