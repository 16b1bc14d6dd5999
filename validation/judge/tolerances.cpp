#include "validation/judge/tolerances.h"

#include <algorithm>
#include <stdexcept>

#include "validation/judge/check_table.h"

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
Tolerances default_tolerances(const std::string& backend, const std::string& precision) {
    Tolerances t;
    if (backend == "event") {
        // Exact dynamics in double: every collision rounds the velocities of two disks, so
        // invariants random-walk by ~eps*sqrt(collisions) (eps = 2.2e-16); 1e-9 allows 1e12
        // collisions. Disks touch at contact to round-off: depth ~ 1e-15 of r_i + r_j.
        t.overlapping_pairs_per_disk = 0.05;  // pairs caught exactly at contact, depth ~1e-16
        return t;
    }
    // A backend that offers both ("float|double") runs the first-listed precision unless asked
    // otherwise, and a validation case does not ask: opencl cases run in float.
    const bool single = precision.rfind("float", 0) == 0;
    if (backend == "box2d") {
        // Sequential impulses with a velocity threshold for restitution and a linear slop
        // of 0.005 m (Box2D 2.4 b2_linearSlop) scaled to the scene: see docs/validation.md.
        t.momentum_drift = 1e-4;
        t.energy_drift = 5e-2;
        t.max_overlap = 0.25;
        t.mean_overlap = 0.05;
        t.overlapping_pairs_per_disk = 1.0;
        t.wall_penetration = 0.25;
        t.trajectory_error = 1.0;
        return t;
    }
    // Stepped rules (step, cpu, opencl): momentum is exchanged in equal and opposite impulses,
    // so only rounding breaks it; energy changes when a disk has several contacts in one step
    // (Jacobi pass) and overlap depth is bounded by the approach speed times dt.
    t.momentum_drift = single ? 1e-4 : 1e-10;
    // Used for the total-energy check under gravity only: the kinetic-energy check at e = 1
    // takes its bound from the rule's own energy-loss model for the case (energy_loss_model.h).
    t.energy_drift = 2e-2;
    t.max_overlap = 0.2;
    t.mean_overlap = 0.05;
    t.overlapping_pairs_per_disk = 0.5;
    t.wall_penetration = 0.2;
    t.trajectory_error = 0.5;
    return t;
}

// A variant "box2d[shipped]" starts from its base's limits (defaults, then [tolerances.box2d])
// and [tolerances."box2d[shipped]"] overrides them.
Tolerances ToleranceTable::for_backend(const std::string& backend, const std::string& precision) const {
    const std::string base = backend.substr(0, backend.find('['));
    Tolerances t = default_tolerances(base, precision);
    for (const auto& [key, value] : all_backends) tolerance_field(t, key) = value;
    for (const std::string& name : {base, backend})  // twice the same name: harmless
        if (auto it = per_backend.find(name); it != per_backend.end())
            for (const auto& [key, value] : it->second) tolerance_field(t, key) = value;
    return t;
}

}  // namespace collide::validation
