// The checks: each turns measurements into a value, compares it with its tolerance and says
// pass, fail or left out (with the reason). Definitions and tolerance derivations are in
// docs/validation.md; the names here are the ones the report and the JUnit file show.
//
//   run                  the case ran to the end (no exception, crash, NaN or time-out)
//   momentum_drift       max_t |P(t) - P(0)| / sqrt(2 M K(0))           (M mobile mass)
//   energy_drift         max_t |E(t) - E(0)| / max_t K(t)               (E kinetic or total)
//   max_overlap          max_t max over pairs of (r_i + r_j - d) / (r_i + r_j)
//   mean_overlap         max_t mean of the same over overlapping pairs
//   overlapping_pairs    max_t (overlapping pairs) / N
//   wall_penetration     max_t max over disks of depth beyond a wall / r
//   trajectory_error     max over output times and disks of |x - x_ref| / r_min
//   pressure             z-score of Z = P/(rho kT) vs the reference, over replicates
//   collision_rate       z-score of collisions per disk per time unit vs the reference
//   speed_distribution   two-sample Kolmogorov-Smirnov p-value of final speeds vs the reference
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "applicability.h"
#include "case_result.h"
#include "tolerances.h"

namespace collide::validation {

enum class CheckStatus { pass, fail, left_out };
const char* to_string(CheckStatus s);

struct CheckResult {
    std::string subject;     // a case id, or a group id (case id without the seed) for statistics
    std::string scene, backend;
    std::string check;
    CheckStatus status = CheckStatus::left_out;
    double value = 0;
    double tolerance = 0;
    std::string comparison = "<=";  // how value relates to tolerance for a pass ("<=" or ">=")
    std::string detail;             // failure message or left-out reason
    std::optional<double> predicted;              // what a model of the rule expects (value's quantity or a difference)
    std::optional<double> predicted_uncertainty;  // its one-standard-deviation uncertainty
};

// The checks of one case on its own (run, conservation, overlaps).
std::vector<CheckResult> case_checks(const CaseResult& result, const SceneFeatures& features,
                                     const Tolerances& tolerances);

// The id of a case's sweep group: the case id without the "__seed<N>" suffix.
std::string group_id(const CaseSpec& spec);

}  // namespace collide::validation
