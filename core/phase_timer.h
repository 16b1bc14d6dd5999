// The phases of a step of the stepping rules, named once for every backend that runs them
// (step, cpu; the OpenCL kernels' comments use the same words) and for SolverStats::phase_seconds:
//   grid       rebuild the broad phase (the uniform grid / cell list)
//   collide    the Jacobi contact pass: every disk's correction from one snapshot
//   correct    apply the corrections, then the walls
//   integrate  forces and Euler (the rule decides whether before or after the contacts)
// PhaseTimer adds the wall time of one phase to a solver's statistics when it goes out of
// scope, so `phase_seconds` means the same in each backend.
#pragma once

#include <chrono>

#include "solver.h"

namespace collide {

namespace phase {
inline constexpr const char* grid = "grid";
inline constexpr const char* collide = "collide";
inline constexpr const char* correct = "correct";
inline constexpr const char* integrate = "integrate";
}  // namespace phase

class PhaseTimer {
public:
    PhaseTimer(SolverStats& stats, const char* phase)
        : stats_(stats), phase_(phase), start_(std::chrono::steady_clock::now()) {}
    ~PhaseTimer() {
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
        stats_.phase_seconds[phase_] += elapsed.count();
    }
    PhaseTimer(const PhaseTimer&) = delete;
    PhaseTimer& operator=(const PhaseTimer&) = delete;

private:
    SolverStats& stats_;
    const char* phase_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace collide
