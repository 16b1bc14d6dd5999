// run_scene: the one loop that drives a solver through a scene's output times, computes the
// metrics at each, and optionally writes them. Used by `collide run`, the validation runner
// and the benchmarks, so all of them measure the same thing.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/metrics.h"
#include "core/io/run_writer.h"
#include "core/solver.h"

namespace collide {

struct RunResult {
    std::vector<Metrics> series;          // metrics at t = 0, interval, 2 interval, ..., duration
    ParticleState<double> final_state;
    double wall_seconds = 0;              // time spent in solver.advance_to() alone
    SolverStats stats;
};

struct RunOptions {
    RunWriter* writer = nullptr;          // write metrics (and frames) here if set
    // Called after each output time with (time, duration); for progress lines.
    std::function<void(double, double)> on_output;
    // Called after each output time with the state and its metrics (validation: observables
    // from snapshots, trajectories). The state is only valid during the call.
    std::function<void(const ParticleState<double>&, const Metrics&)> on_state;
    // Stop with an error when a metric shows NaN/Inf (the default: a run that has produced
    // NaN cannot recover, and its later output would be meaningless).
    bool stop_on_nonfinite = true;
};

// Loads `initial` into `solver` and runs it to scene.run.duration.
RunResult run_scene(const Scene& scene, Solver& solver, const ParticleState<double>& initial,
                    const RunOptions& options = {});

// Why a run must stop at the state and metrics `m` (taken at m.time), in the words of a
// stopped `collide run`, or "" when every disk and metric is finite. E.g.
//   "step: 3 disk(s) with NaN/Inf state at t = 0.5 (first: disk 17, x = (...), v = (...));
//   every disk was finite at t = 0.4: the state broke in between (NARROWER narrows it down)"
// m.time <= last_finite_t says the state held it from the start. run_scene and the Python
// module's Simulation use it, so both stop at the same states with the same words.
std::string nonfinite_problem(const std::string& solver_name, const ParticleState<double>& state, const Metrics& m,
                              double last_finite_t, const std::string& narrower);

// The output times of a scene: 0, interval, ..., duration (the last one exactly `duration`).
std::vector<double> output_times(const Scene& scene);

}  // namespace collide
