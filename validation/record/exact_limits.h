// The limits of an exact solver: what exact dynamics computed in a given precision allows, and
// no more (docs/validation.md, "What a solver claims"). A solver that declares itself exact
// (BackendInfo::exact, `[solver.NAME] exact = true`) is held to these on every case; a defect
// that acts at a collision (a restitution of 0.995, a skipped collision) moves an invariant by
// far more than rounding does and fails.
#pragma once

#include <cstdint>
#include <optional>

#include "core/scene/scene.h"
#include "validation/record/tolerances.h"
#include "validation/record/case_result.h"

namespace collide::validation {

// Units of rounding (epsilon of the precision) one pair collision may move the momentum or the
// kinetic energy by, relative to the checks' scales: the new velocities come out of about ten
// rounded operations, each off by at most one epsilon relative, and the pair holds at most all
// of the momentum scale and of the kinetic energy. A bound, not the typical value: the errors
// of successive collisions are of either sign and add as a random walk (sqrt(C), not C).
inline constexpr double conservation_epsilons_per_collision = 16;
// Units of rounding a disk centre's coordinate may be off by, relative to the largest
// coordinate L of the box: a contact is predicted from positions that carry rounding of order
// epsilon L, so two disks meet at their contact distance sigma up to a depth of that order, and
// the relative depth is of order epsilon L / sigma. The factor covers the few updates between
// prediction and contact and the subtraction of two rounded coordinates.
inline constexpr double position_epsilons = 64;

// The collision count taken for a case whose run has no reference to count them (a suite
// without `event`): the limits then allow 16 eps (1e6 + 1) = 3.6e-9 in double.
inline constexpr std::int64_t collisions_without_reference = 1'000'000;

// What rounding depends on in one case.
struct RoundingScale {
    // The case's pair collisions, as the reference run of its scene, parameters and seed counted
    // them (an outside solver need not report its own); nullopt when the run has no reference.
    std::optional<std::int64_t> collisions;
    double coordinate = 0;       // L: the largest |coordinate| of the box
    double smallest_radius = 0;  // r_min of the case's disks
};

// Machine epsilon of the precision a backend declares: 2.2e-16 (double), 1.2e-7 (float).
double machine_epsilon(bool single_precision);

// The scale of `result`, a case of `scene`, whose reference run is `reference` (nullptr: none;
// an unfinished reference counts no collisions either).
RoundingScale rounding_scale(const CaseResult& result, const Scene& scene, const CaseResult* reference);

// Sets the conservation and overlap limits of `t` to what rounding allows in `scale`:
//   momentum_drift, energy_drift <= conservation_epsilons_per_collision * eps * (C + 1)
//   max_overlap, mean_overlap,
//   overlap_beyond_step          <= position_epsilons * eps * L / (2 r_min)   (contact distance)
//   wall_penetration             <= position_epsilons * eps * L / r_min
// C is collisions_without_reference when the count is unknown; the overlap limits keep their
// value in `t` when the scale is (no disks).
void apply_exact_limits(Tolerances& t, double epsilon, const RoundingScale& scale);

// conservation_epsilons_per_collision * eps * (C + 1): how far rounding alone moves a conserved
// sum over C collisions in the precision of `epsilon` (the + 1: the metric's own sums).
double conservation_rounding(double epsilon, std::int64_t collisions);

// position_epsilons * eps * L / (2 r_min): the relative depth at contact that rounding of the
// positions alone can leave, in the precision of `epsilon`; nullopt when the scale is unknown.
std::optional<double> contact_rounding(double epsilon, const RoundingScale& scale);

}  // namespace collide::validation
