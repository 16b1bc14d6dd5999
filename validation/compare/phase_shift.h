// Collision-phase replicates for trajectory comparisons.
//
// A time-stepped rule finds a collision at the first step whose end state overlaps, so its
// position error after the collision depends on the *phase* of the exact collision time
// within a step, frac(t_c / dt). In a scene written by hand t_c is often a round number
// (head-on at t = 1.5) and, for some dt of a sweep, the collision falls exactly on a step
// boundary: the error drops to rounding for that dt and a fitted convergence order is
// meaningless. Replicates therefore start the same scene at different phases: replicate k
// of a case with step dt advances the initial state by free flight for
//     delta_k = frac(k * phi) * dt,     phi = (sqrt 5 - 1)/2 (golden ratio),
// so its collision phase is shifted by frac(k phi), the most evenly spread sequence of
// fractions for any number of replicates (Weyl's equidistribution with the golden ratio).
// Every replicate is shifted, the first included (by 0.618 dt): a shift of 0 would keep the
// scene's round collision time, on a step boundary for some dt, the very case the phases are
// there to avoid. frac(k phi) is never 0 for k >= 1 since phi is irrational. The reference backend runs once per (seed, dt) from the
// same shifted state, so every comparison is exact-vs-rule on the same initial condition, and
// the error of each sweep point is a mean over phases with its standard error.
#pragma once

#include <cstdint>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide::validation {

// The time-origin shift of replicate `seed` (1-based) for a case with time step dt.
double phase_shift(std::uint64_t seed, double dt);

// Moves every non-stone disk along its free-flight path (under the scene's gravity) for
// `delta`. Contacts during the shift are not resolved: keep delta below the first collision.
void advance_free_flight(const Scene& scene, ParticleState<double>& state, double delta);

}  // namespace collide::validation
