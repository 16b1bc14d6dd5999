// Input checks shared by the two event-driven solvers (`event` and `event-plain`): both
// refuse the same initial states with the same messages, so they cannot disagree on what a
// valid hard-disk start is.
#pragma once

#include <optional>
#include <string>

#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "core/scene/scene_features.h"

namespace collide {

// What neither event-driven solver models, with the reason (empty if the scene is inside the
// model): friction and damping (no free flight between events), and gravity with stones (a
// quartic collision time). Each solver adds its own limits after these.
std::optional<std::string> outside_event_model(const SceneFeatures& features);

// Initial states may touch or reach a wall to within this fraction of the contact distance
// (e.g. a lattice with spacing exactly 2r, rounded); anything deeper is an input error.
inline constexpr double hard_disk_overlap_tolerance = 1e-10;

// Restitutions in [0, 1], radii and masses > 0, finite positions and velocities, disks inside
// the walls (reflecting box), numbers representable in double (core/numerics/representability.h), and
// a run that can finish. `who` starts every
// message ("event", "event-plain"). Throws std::runtime_error.
void check_hard_disk_input(const std::string& who, const Scene& scene, const ParticleState<double>& state);

// An event-driven run's cost grows with its events, not its duration: refuses a run whose disks
// would cross the box more than 1e12 times (called after the representability check, so a speed
// that does not fit is named as such first).
void reject_endless_run(const std::string& who, const Scene& scene, const ParticleState<double>& state);

// Throws if two disks overlap by more than the tolerance, naming the pair. In a periodic box
// the positions must already lie inside it (the pair search bins them into cells).
void reject_overlapping_disks(const std::string& who, const Scene& scene, const ParticleState<double>& state);

}  // namespace collide
