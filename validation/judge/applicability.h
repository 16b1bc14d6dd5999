// Which checks a scene's physics guarantees ("Leave out what a scene does not need"): an
// invariant is checked only where the exact dynamics conserves it, and a left-out check is
// reported with the reason, never silently passed.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "core/scene/scene_features.h"

namespace collide::validation {

// The features that decide which checks apply are core's SceneFeatures (core/scene/scene_features.h),
// computed once per scene and its initial state (scene_features(scene, initial)).

// Total momentum is conserved when no external force acts: no reflecting walls (they push
// back), no gravity, no drag, no stones (infinite mass absorbs any momentum).
std::optional<std::string> momentum_left_out(const SceneFeatures& f);

enum class EnergyKind { none, kinetic, total };
struct EnergyCheck {
    EnergyKind kind = EnergyKind::none;
    std::string reason;  // why left out (kind = none), or a note on the kind chosen
};
// Kinetic energy is conserved with e = 1, wall e = 1 (if there are walls), no damping, no
// friction, no gravity and no moving stones; with gravity and otherwise the same conditions
// the total energy (kinetic + potential) is conserved instead.
EnergyCheck energy_check(const SceneFeatures& f);

// Periodic boxes have no walls to penetrate.
std::optional<std::string> wall_penetration_left_out(const SceneFeatures& f);

// The count of overlapping pairs per disk judges a population: it is judged only where its limit
// allows at least this many overlapping pairs (limit x N). Below that it counts single pairs
// (0, 1/N, 2/N, ...): one honest pair met in the last step, which a stepping rule shows at an
// output now and then, would fail it, and where (N - 1) / 2 is within the limit (two disks at
// 0.5) nothing could. Such a count is left out, not passed, and overlap_beyond_step judges in
// its place. The threshold, overlapping_pairs_counted_from, is in check_table.h (summary.json's
// `quantised` marks the same counts).
std::optional<std::string> overlapping_pairs_too_few(std::size_t disks, double limit_per_disk);

// overlap_beyond_step (a pair overlapped deeper than one step of its approach: it stayed
// overlapped for more than one step) replaces overlapping_pairs where that count cannot fail,
// and is left out where it can.
std::optional<std::string> overlap_beyond_step_left_out(std::size_t disks, double limit_per_disk);

// The contact-value pressure estimator needs one disk diameter.
std::optional<std::string> pressure_left_out(const SceneFeatures& f);

}  // namespace collide::validation
