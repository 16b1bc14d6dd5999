#include "validation/record/tolerances.h"

#include <algorithm>
#include <stdexcept>

#include "validation/record/check_table.h"
#include "validation/record/exact_limits.h"

namespace collide::validation {

// The keys and the fields they set come from the check table: one key may bound several
// checks (statistics_z: pressure and collision_rate).
const std::vector<std::string>& tolerance_keys() {
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> out;
        for (const CheckDefinition& c : check_table)
            if (c.tolerance && std::find(out.begin(), out.end(), c.tolerance_key) == out.end()) out.push_back(c.tolerance_key);
        return out;
    }();
    return keys;
}

double& tolerance_field(Tolerances& t, const std::string& key) {
    for (const CheckDefinition& c : check_table)
        if (c.tolerance && key == c.tolerance_key) return t.*c.tolerance;
    std::string names;
    for (const auto& k : tolerance_keys()) names += (names.empty() ? "" : ", ") + k;
    throw std::invalid_argument("unknown tolerance '" + key + "'; expected one of: " + names);
}

double tolerance_value(const Tolerances& t, const std::string& key) {
    Tolerances copy = t;
    return tolerance_field(copy, key);
}

// Each number is derived in docs/validation.md; the comments give the one-line reason.
Tolerances default_tolerances(const BackendInfo& backend, const RoundingScale& scale) {
    Tolerances t;
    if (backend.exact || backend.sampler) {
        // Exact dynamics: conserved sums move by rounding at each collision and disks touch at
        // contact up to the rounding of their positions (exact_limits.h). A sampler's lift
        // leaves a pair touching to the same rounding; its conservation checks are left out.
        apply_exact_limits(t, machine_epsilon(backend.single_precision()), scale);
        t.overlapping_pairs_per_disk = 0.05;  // pairs caught exactly at contact, depth ~1e-16
        return t;
    }
    if (!backend.stepping_rule() && !backend.limits.empty()) {
        // Limits of its own, derived for its method (box2d: docs/validation.md).
        for (const auto& [key, value] : backend.limits) tolerance_field(t, key) = value;
        return t;
    }
    // Stepped rules (and a solver that declares nothing): momentum is exchanged in equal and
    // opposite impulses, so only rounding breaks it; energy changes when a disk has several
    // contacts in one step (Jacobi pass) and overlap depth is bounded by the approach speed
    // times dt. A backend that offers both precisions ("float|double") runs the first-listed
    // unless asked otherwise, and a validation case does not ask: opencl cases run in float.
    const bool single = backend.single_precision();
    t.momentum_drift = single ? 1e-4 : 1e-10;
    // Used for the total-energy check under gravity only: the kinetic-energy check at e = 1
    // takes its bound from the rule's own energy-loss model for the case (energy_loss_model.h).
    t.energy_drift = 2e-2;
    t.max_overlap = 0.2;
    t.mean_overlap = 0.05;
    // Pairs that met in the last step: nu h / 2 per disk on average (0.004 in periodic_gas at
    // dt = 6e-3), 0.0146 measured at most over the default suite (stones_and_gas at dt = 4e-3,
    // 2026-11-29). Missing every collision (free
    // flight, uniform positions) overlaps n pi sigma^2 / 2 = 2 phi pairs per disk: 0.44 in
    // periodic_gas, which the former 0.5 let pass (tests/validation/test_checks_can_fail.cpp).
    // A pile at rest under gravity keeps its contacts overlapped by design (particle_box: 1.8
    // per disk): a suite that judges one sets its own limit.
    t.overlapping_pairs_per_disk = 0.1;
    // A rule removes an overlap in the step that detects it, so at an output a pair is at most
    // as deep as its own approach in one step |v_i - v_j| h; what is left beyond that is the
    // rounding of the positions in the backend's precision (metrics.cpp: OverlapTally). A pair
    // left overlapped one step more is up to |v_i - v_j| h / (r_i + r_j) deeper (half that on
    // average over where in the step it met): 5e-4 at the default suite's finest sweep point
    // (relative speed 2, h = 2.5e-4, r_i + r_j = 1), 6.6 x the float rounding of 7.6e-5 there
    // (L = 10).
    if (const auto depth = contact_rounding(machine_epsilon(single), scale)) t.overlap_beyond_step = *depth;
    // A solver that declares no rule does not promise to remove an overlap in the step that finds
    // it: an engine's contact solver leaves its slop (planck as shipped: 0.5 % of a unit radius,
    // 1.7e-3 measured) and corrects positions over several steps; it gets a contact solver's
    // limit (sequential_impulse_limits in apps/all_backends.cpp: 1e-2), not the rules' rounding.
    if (!backend.stepping_rule()) t.overlap_beyond_step = 1e-2;
    t.wall_penetration = 0.2;
    t.trajectory_error = 0.5;
    return t;
}

Tolerances default_tolerances(const BackendInfo& backend) { return default_tolerances(backend, RoundingScale{}); }

// A variant "box2d[shipped]" starts from its base's limits (defaults, then [tolerances.box2d])
// and [tolerances."box2d[shipped]"] overrides them.
void ToleranceTable::apply_overrides(Tolerances& t, const std::string& backend) const {
    const auto set = [&t](const std::string& key, double value) {
        tolerance_field(t, key) = value;
        t.set_by_suite.insert(key);
    };
    const std::string base = backend.substr(0, backend.find('['));
    for (const auto& [key, value] : all_backends) set(key, value);
    for (const std::string& name : {base, backend})  // twice the same name: harmless
        if (auto it = per_backend.find(name); it != per_backend.end())
            for (const auto& [key, value] : it->second) set(key, value);
}

Tolerances ToleranceTable::for_backend(const BackendInfo& backend) const {
    Tolerances t = default_tolerances(backend);
    apply_overrides(t, backend.name);
    return t;
}

Tolerances ToleranceTable::for_case(const BackendInfo& backend, const RoundingScale& scale) const {
    Tolerances t = default_tolerances(backend, scale);
    apply_overrides(t, backend.name);
    return t;
}

}  // namespace collide::validation
