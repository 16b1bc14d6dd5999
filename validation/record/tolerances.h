// Tolerances: the limit each check compares its value against, per backend. The defaults
// below are derived in docs/validation.md ("How each tolerance was derived"); a suite can
// override any of them in [tolerances.default] or [tolerances.<backend>].
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/backend_registry.h"

namespace collide::validation {

// One limit per [tolerances] key; every value is a bound on a dimensionless number. Which
// check each bounds, and what it divides by: the check table (check_table.h).
struct Tolerances {
    double momentum_drift = 1e-9;
    double energy_drift = 1e-9;
    double max_overlap = 1e-9;
    double mean_overlap = 1e-9;
    double overlapping_pairs_per_disk = 0.01;
    double overlap_beyond_step = 1e-9;
    double wall_penetration = 1e-9;
    double trajectory_error = 1e-6;   // in units of the smallest radius
    double statistics_z = 4.0;        // |difference| / combined standard error
    double speed_ks_p_value = 1e-3;   // two-sample Kolmogorov-Smirnov p-value must exceed this

    // The keys a suite set ([tolerances.default], [tolerances.<backend>]); every other limit is
    // the backend's default. A check that replaces a default in a special case (checks.cpp: an
    // isolated contact of a contact solver) leaves a limit the suite chose alone, whatever its
    // value, even one equal to the default.
    std::set<std::string> set_by_suite;
    bool suite_set(const std::string& key) const { return set_by_suite.count(key) > 0; }
};

// The [tolerances] keys of suite files, in the check table's order (check_table.h).
const std::vector<std::string>& tolerance_keys();
double& tolerance_field(Tolerances& t, const std::string& key);  // throws on an unknown key
double tolerance_value(const Tolerances& t, const std::string& key);

struct RoundingScale;  // exact_limits.h

// Defaults from what the backend declares (BackendInfo: exact, rule, precision, limits), before
// any suite override; never from its name. Exact: rounding-level limits at the scale of a case
// (exact_limits.h; without a scale, the largest a case of that solver could need); a stepping
// rule: the rule's (double or float); limits of its own (box2d); otherwise, for a solver that
// declares nothing, the loose limits of the stepped rules.
Tolerances default_tolerances(const BackendInfo& backend);
Tolerances default_tolerances(const BackendInfo& backend, const RoundingScale& scale);

// [tolerances.default] and [tolerances.<backend>] of a suite: key -> value overrides.
struct ToleranceTable {
    std::map<std::string, double> all_backends;
    std::map<std::string, std::map<std::string, double>> per_backend;

    // The backend's limits: its defaults, then [tolerances.default], [tolerances.BASE] and
    // [tolerances."BASE[VARIANT]"] (a variant inherits its base's declarations and overrides).
    Tolerances for_backend(const BackendInfo& backend) const;
    // The same for one case: an exact backend's limits at the case's rounding scale.
    Tolerances for_case(const BackendInfo& backend, const RoundingScale& scale) const;

private:
    void apply_overrides(Tolerances& t, const std::string& backend) const;
};

}  // namespace collide::validation
