// run_scene: the one loop that drives a solver through a scene's output times, computes the
// metrics at each, and optionally writes them. Used by `collide run`, the validation runner
// and the benchmarks, so all of them measure the same thing.
#pragma once

#include <functional>
#include <vector>

#include "metrics.h"
#include "run_writer.h"
#include "solver.h"

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

// The output times of a scene: 0, interval, ..., duration (the last one exactly `duration`).
std::vector<double> output_times(const Scene& scene);

}  // namespace collide
