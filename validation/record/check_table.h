// The checks of a validation suite, declared once: each check's name (as the report, the JUnit
// file, summary.json and a variant's leave_out spell it), what it measures, when it passes, the
// [tolerances] key that bounds it, when it applies and why, and the function that computes it.
//
// Read by: the case checks (checks.cpp: the per-case checks, in this order), the comparisons
// with the reference (reference_comparison.cpp), the tolerances (tolerances.cpp: the keys and
// the Tolerances field each names), the suite reader (suite.cpp: which names leave_out may
// list), summary.json (`check_definitions`, the order and metadata the report shows), and
// docs/validation.md, whose table of checks a test holds to this one
// (tests/validation/test_check_table.cpp).
#pragma once

#include <cstddef>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "validation/record/tolerances.h"

namespace collide::validation {

enum class CheckKind {
    case_check,   // one case on its own (checks.cpp: case_checks)
    trajectory,   // compare = "trajectory": each case against the reference run of its seed
    statistics,   // compare = "statistics": a group of replicates against the reference's
                  // (both in reference_comparison.cpp: compare_with_reference)
    stability,    // stability suites only: the case's outcome class (stability.cpp)
};

struct CheckDefinition {
    const char* name;
    CheckKind kind;
    const char* measures;       // the value the check computes
    const char* passes_when;    // how the value relates to its bound for a pass
    const char* tolerance_key;  // the suite's [tolerances] key, "" when the check has no single bound
    double Tolerances::*tolerance;  // the field that key sets; nullptr with ""
    const char* applies;        // when the check is judged, and why it is left out otherwise
    const char* computed_by;    // the function that computes it (file: function)
};

inline constexpr CheckDefinition check_table[] = {
    {"run", CheckKind::case_check, "the case ran to the end",
     "no exception, crash, NaN/Inf (in the state or in any metric) or time-out", "", nullptr,
     "every case", "checks.cpp: case_checks"},
    {"momentum_drift", CheckKind::case_check, "max_t |P(t) - P(0)| / sqrt(2 M K(0))", "<= tolerance",
     "momentum_drift", &Tolerances::momentum_drift,
     "no reflecting walls, gravity, damping or stones: each is an external force or an infinite mass",
     "applicability.cpp: momentum_left_out; checks.cpp: momentum_drift"},
    {"energy_drift", CheckKind::case_check, "max_t |E(t) - E(0)| / max_t K(t)", "<= tolerance",
     "energy_drift", &Tolerances::energy_drift,
     "e = 1 (and wall e = 1 with walls), no damping, no friction, no moving stones: else energy is not "
     "conserved; E is the total energy under gravity, the kinetic energy otherwise",
     "applicability.cpp: energy_check; checks.cpp: energy_drift"},
    {"max_overlap", CheckKind::case_check, "max_t max over pairs of (r_i + r_j - d)/(r_i + r_j)", "<= tolerance",
     "max_overlap", &Tolerances::max_overlap, "every finished case", "checks.cpp: case_checks"},
    {"mean_overlap", CheckKind::case_check, "max_t mean of the same over overlapping pairs", "<= tolerance",
     "mean_overlap", &Tolerances::mean_overlap, "every finished case", "checks.cpp: case_checks"},
    {"overlapping_pairs", CheckKind::case_check, "max_t (number of overlapping pairs) / N", "<= tolerance",
     "overlapping_pairs_per_disk", &Tolerances::overlapping_pairs_per_disk,
     "every finished case where the limit allows at least 10 overlapping pairs (limit × N ≥ 10)", "checks.cpp: case_checks"},
    {"overlap_beyond_step", CheckKind::case_check,
     "max_t max over overlapping pairs of (r_i + r_j - d - |v_i - v_j| h)/(r_i + r_j), h = dt / substeps",
     "<= tolerance", "overlap_beyond_step", &Tolerances::overlap_beyond_step,
     "where overlapping_pairs is left out (limit × N < 10: few disks), in its place: a pair deeper than one step of its approach "
     "has stayed overlapped for more than one step",
     "metrics.cpp: OverlapTally; applicability.cpp: overlap_beyond_step_left_out; checks.cpp: case_checks"},
    {"wall_penetration", CheckKind::case_check, "max_t max over disks of (depth beyond a wall) / r", "<= tolerance",
     "wall_penetration", &Tolerances::wall_penetration, "reflecting walls: a periodic box has none",
     "applicability.cpp: wall_penetration_left_out; checks.cpp: case_checks"},
    {"trajectory_error", CheckKind::trajectory,
     "max over output times t <= T_h (the predictability horizon) and disks of |x - x_ref| / r_min",
     "<= tolerance; a solver claiming exact dynamics in double: <= 1000 x the reference twins' separation at t",
     "trajectory_error", &Tolerances::trajectory_error,
     "compare = \"trajectory\" (few bodies), against the reference run of the same seed, up to its predictability "
     "horizon; not judged where the horizon is shorter than the first output time",
     "reference_comparison.cpp: trajectory_check; predictability_horizon.cpp"},
    {"pressure", CheckKind::statistics,
     "z-score of Z = P/(rho kT) against the reference, over replicates (stepped backends: against the reference "
     "plus the rule's predicted bias)",
     "<= statistics_z", "statistics_z", &Tolerances::statistics_z,
     "compare = \"statistics\", and one disk diameter: the contact-value estimator needs it",
     "applicability.cpp: pressure_left_out; reference_comparison.cpp: z_check"},
    {"collision_rate", CheckKind::statistics,
     "z-score of collisions per disk per time unit, over replicates (stepped backends: as for pressure)",
     "<= statistics_z", "statistics_z", &Tolerances::statistics_z, "compare = \"statistics\"",
     "reference_comparison.cpp: z_check"},
    {"speed_distribution", CheckKind::statistics, "two-sample Kolmogorov-Smirnov p-value of final speeds",
     ">= speed_ks_p_value", "speed_ks_p_value", &Tolerances::speed_ks_p_value, "compare = \"statistics\"",
     "reference_comparison.cpp: pooled_speeds, ks_two_sample"},
    {"stability", CheckKind::stability, "the case's outcome: stable, or how it failed (docs/stability.md)",
     "stable", "", nullptr, "suites with stability = true", "stability.cpp: classify"},
};

inline constexpr std::size_t check_count = std::size(check_table);

// overlapping_pairs is judged only where its limit allows at least this many overlapping pairs
// (limit x N): below that it counts single pairs (applicability.h: overlapping_pairs_too_few).
inline constexpr double overlapping_pairs_counted_from = 10;

// The check named `name`, or nullptr.
inline const CheckDefinition* find_check(std::string_view name) {
    for (const CheckDefinition& c : check_table)
        if (name == c.name) return &c;
    return nullptr;
}

// The names of the checks of one kind, in table order.
std::vector<std::string> check_names(CheckKind kind);

}  // namespace collide::validation
