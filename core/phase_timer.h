// PhaseTimer: adds the wall time of one phase of a step (grid, collide, correct, integrate) to
// a solver's statistics when it goes out of scope. The stepping backends time their phases
// with it, so `SolverStats::phase_seconds` means the same in each.
#pragma once

#include <chrono>

#include "solver.h"

namespace collide {

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
