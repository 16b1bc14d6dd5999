// The phases of a step of the stepping rules, named once for every backend that runs them
// (step, cpu; the OpenCL kernels carry the same names) and for SolverStats::phase_seconds:
//   grid       rebuild the broad phase (the uniform grid / cell list)
//   collide    the Jacobi contact pass: every disk's correction from one snapshot
//   correct    apply the corrections, then the walls
//   integrate  forces and Euler (the rule decides whether before or after the contacts)
// PhaseTimer adds the wall time of one phase to a solver's statistics when it goes out of
// scope, so `phase_seconds` means the same in each backend.
#pragma once

#include <chrono>

#include "core/solver.h"

namespace collide {

namespace phase {
inline constexpr const char* grid = "grid";
inline constexpr const char* collide = "collide";
inline constexpr const char* correct = "correct";
inline constexpr const char* integrate = "integrate";
// The `opencl` backend times what the host sees. Its kernels (collide_and_correct, integrate)
// run asynchronously, so a step's device work is one phase; the grid build and the transfers
// around it are timed apart (docs/opencl-backend.md).
inline constexpr const char* device_steps = "kernels";
inline constexpr const char* grid_on_device = "grid (device)";
inline constexpr const char* grid_on_host = "grid (host)";
inline constexpr const char* upload = "upload";
inline constexpr const char* read_back = "read-back";
inline constexpr const char* reorder = "reorder";
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
