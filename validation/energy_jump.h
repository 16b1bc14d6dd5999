// Energy jumps attributed: the step of a stepped run in which the kinetic energy changed most,
// the disks that step changed, and the kind of contact behind it (an isolated pair, several
// disks in contact at once, a disk at a wall). At e = 1 an isolated pair keeps its energy
// exactly (docs/stepping-rules.md, section 1); the stepped rules lose or gain it where one disk
// takes two or more impulses computed from one snapshot (section "Energy at e = 1"). The report
// names every jump it shows this way (`collide explain`, docs/reading-a-report.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/particle_state.h"
#include "core/scene.h"
#include "core/solver.h"

namespace collide::validation {

struct JumpDisk {
    std::size_t index = 0;                  // the disk's index in the scene (0-based)
    double kinetic_before = 0, kinetic_after = 0;
};

// A set of changed disks linked by contacts in one step, with the walls they touched.
struct ContactGroup {
    std::string kind;                                    // see contact_kind()
    std::vector<JumpDisk> disks;                         // ascending index
    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // disk contacts (i < j)
    std::vector<std::pair<std::size_t, std::string>> walls;  // (disk, "left"/"right"/"bottom"/"top")
    double kinetic_change = 0;                           // sum of the disks' changes
};

struct EnergyJump {
    std::int64_t step = 0;        // the step's index from t = 0 (one step = one dt)
    double time_before = 0, time_after = 0;
    double kinetic_before = 0;    // total kinetic energy before the step
    double kinetic_change = 0;    // total change over the step
    std::vector<ContactGroup> groups;  // largest |kinetic_change| first
};

// The kind of a group, in words: "an isolated pair", "3 disks in contact at once", "a disk at
// a wall", "a disk touching a wall and a disk", "3 disks and a wall", "no contact (a force)".
std::string contact_kind(std::size_t disks, std::size_t pairs, std::size_t walls);

// The disks whose velocity a contact changed between two states one step apart (beyond what
// gravity and damping give, and above rounding: 1e-9 of the rms speed), grouped by the
// contacts the step can have seen: a pair within contact distance (1e-6 relative slack) before or after the step, a
// disk within its radius of a reflecting wall. Periodic scenes use the nearest image.
std::vector<ContactGroup> attribute_change(const Scene& scene, const ParticleState<double>& before,
                                           const ParticleState<double>& after);

// Steps a loaded solver from its current time to t_end one dt at a time (advance_to the next
// whole multiple of dt) and returns the step whose total kinetic energy change is largest in
// magnitude, attributed. Throws std::runtime_error when t_end is not after the current time.
EnergyJump largest_energy_change(Solver& solver, const Scene& scene, double t_end);

// One line: "the step ending at t = 1.036 changes K by -5.778 (-0.584 % of K); 3 disks in
// contact at once (disk 72 touches 545 and 839) held 13.5 and keep 7.722 (-42.8 %); 1 other
// group changed less".
std::string describe(const EnergyJump& jump);

}  // namespace collide::validation
