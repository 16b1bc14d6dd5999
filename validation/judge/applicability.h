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

// A count per disk that cannot exceed its limit: N disks overlap in at most N (N - 1) / 2 pairs,
// (N - 1) / 2 per disk, so with two disks (0.5) a limit of 0.5 passes every disk overlapping.
// Such a check is left out (max_overlap and mean_overlap judge the depth there), not passed.
std::optional<std::string> overlapping_pairs_cannot_fail(std::size_t disks, double limit_per_disk);

// The contact-value pressure estimator needs one disk diameter.
std::optional<std::string> pressure_left_out(const SceneFeatures& f);

}  // namespace collide::validation
