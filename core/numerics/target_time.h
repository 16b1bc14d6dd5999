// The one check of a time a solver is asked to advance to. Every backend's advance_to, the
// Python module and the scene reader's [run] rules use it, so that each refuses the same
// times with the same words (docs/refusals.md).
#pragma once

#include <string>

namespace collide {

// The most steps of dt a run may take: more would not finish in any reasonable time (10^12
// steps of one disk take hours) and usually means a unit mistake. The event solver has no
// steps, but its scene has a dt and it obeys the same cap, so that no backend accepts a
// target another refuses.
constexpr double max_steps = 1e12;

// "at most 1000000000000 steps of dt = DT (this is N steps)" when t / dt rounds to more than
// max_steps steps, or "" when it does not (the words after "expected" in a scene error).
std::string steps_cap_problem(double t, double dt);

// Why a solver at time `now` may not advance to `t`, or "" when it may: t is NaN or infinite,
// t needs more than max_steps steps of dt, or t lies before now. `whole_steps`: the solver
// rounds t to whole steps of dt (the stepped backends), so a t that rounds to the current
// step is not in the past.
std::string target_time_problem(double t, double now, double dt, bool whole_steps);

// Throws std::invalid_argument("BACKEND: PROBLEM") when target_time_problem finds one. A
// refused target changes nothing: every caller checks before any work.
void check_target_time(const std::string& backend, double t, double now, double dt, bool whole_steps);

}  // namespace collide
