// Energy jumps attributed: the step of a stepped run in which the energy changed most, the
// disks that step changed, and the kind of contact behind it (an isolated pair, several disks
// in contact at once, a disk at a wall or a stone). At e = 1 an isolated pair keeps its energy
// exactly (docs/stepping-rules.md, section 1); the stepped rules lose or gain it where one disk
// takes two or more impulses computed from one snapshot (section 7, "Energy at e = 1"). The
// report names every jump it shows this way (`collide explain`, docs/reading-a-report.md).
//
// "Energy" is the mechanical energy: kinetic plus gravitational potential, -m g.x, so that a
// step of free fall under gravity is no jump.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "core/solver.h"

namespace collide::validation {

struct JumpDisk {
    std::size_t index = 0;                // the disk's index in the scene (0-based)
    double energy_before = 0, energy_after = 0;
};

// A set of changed disks linked by contacts in one step, with the walls and stones they touched.
struct ContactGroup {
    std::string kind;                                         // see contact_kind()
    std::vector<JumpDisk> disks;                              // ascending index
    std::vector<std::pair<std::size_t, std::size_t>> pairs;   // disk contacts (i < j)
    std::vector<std::pair<std::size_t, std::string>> walls;   // (disk, "left"/"right"/"bottom"/"top")
    std::vector<std::pair<std::size_t, std::size_t>> stones;  // (disk, stone it touched)
    double energy_change = 0;                                 // sum of the disks' changes
};

struct EnergyJump {
    std::int64_t step = 0;        // the step's index from t = 0 (one step = one dt)
    double time_before = 0, time_after = 0;
    double kinetic_before = 0;    // total kinetic energy before the step
    double energy_change = 0;     // total mechanical energy change over the step
    bool nonfinite = false;       // the step made the state non-finite (NaN or infinite)
    std::vector<ContactGroup> groups;  // largest |energy_change| first
};

// The kind of a group, in words: "an isolated pair", "3 disks in contact at once", "a disk at
// a wall", "a disk at 2 walls", "a disk touching a stone and a disk", "4 disks in contact at
// once, with a wall", "no contact found". Walls are counted once each, however many disks
// touched them.
std::string contact_kind(std::size_t disks, std::size_t pairs, std::size_t walls, std::size_t stones);

// The disks whose velocity a contact changed between two states one step apart (beyond what
// gravity and damping give, and above rounding: 1e-9 of the rms speed), grouped by the
// contacts the step can have seen: a pair, or a disk and a stone, within contact distance
// plus what they can travel in one step (so that contacts in a sub-step count) before or after
// it; a disk within the same reach of a reflecting wall. Periodic scenes use the nearest image.
std::vector<ContactGroup> attribute_change(const Scene& scene, const ParticleState<double>& before,
                                           const ParticleState<double>& after);

// The times largest_energy_change advances a solver at time `from` to: each whole multiple of dt
// after `from` up to t_end (empty when none lies there). Exposed so that a caller can announce
// them first (Solver::plan_outputs): an outside solver then makes one program call for the whole
// search instead of one per step.
std::vector<double> step_times(double from, double dt, double t_end);

// Steps a loaded solver from its current time to t_end one dt at a time (advance_to the next
// whole multiple of dt) and returns the step whose mechanical energy change is largest in
// magnitude, attributed; or the first step after which the state is not finite. Throws
// std::runtime_error when no whole step lies before t_end. `on_step(t, t_end)`, if given, is
// called after each step (a progress line for a long search).
EnergyJump largest_energy_change(Solver& solver, const Scene& scene, double t_end,
                                 const std::function<void(double, double)>& on_step = {});

// One line: "the step ending at t = 1.036 changes the energy by -5.778 (-0.584 % of K);
// 3 disks in contact at once (disk 72 touches 545 and 839): 13.5 before, 7.72 after (-42.8 %);
// 1 other group changed less".
std::string describe(const EnergyJump& jump);

}  // namespace collide::validation
