// collide.Simulation: one backend's solver, driven from Python. The state it shows is always a
// copy read with Solver::read_state (double, the scene's disk order), so NumPy arrays handed
// out never point into the solver and stay valid after the Simulation is gone.
#pragma once

#include <memory>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "core/backend_registry.h"
#include "core/metrics.h"
#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "initialised_caster.h"

namespace collide::python {

// Backend options from Python keywords, taken as the CLI and a scene file take them: threads,
// real and device are the command line's --threads, --real and --cl-device; every other
// keyword is a key of the scene's [backend.NAME] table for `backend` (replacing the file's
// value), so it is refused where a scene file's key would be, with the same words: here (a key
// under [backend.step], a value that is no string, number or boolean) or when the backend
// loads the scene (an unknown key, a malformed value). None leaves a keyword out.
BackendOptions backend_options(const pybind11::kwargs& options, const std::string& backend, Scene& scene);

// The backend called `name`, checked against the scene with the CLI's message when it cannot run it.
const BackendInfo& backend_for(const Scene& scene, const std::string& name);

// An (N, 2) or (N,) float64 array holding a copy, marked read-only.
pybind11::array_t<double> read_only_pairs(const std::vector<double>& a, const std::vector<double>& b);
pybind11::array_t<double> read_only_array(const std::vector<double>& a);

class Simulation {
public:
    Simulation(const Scene& scene, const std::string& backend, const BackendOptions& options);

    // Advances to absolute time t in chunks with the GIL released, checking for Ctrl-C
    // between chunks (KeyboardInterrupt leaves the simulation at the last chunk's end, valid).
    // Refuses (ValueError, nothing done) a t that is not finite, in the past or beyond the
    // CLI's cap of max_steps steps; raises RuntimeError with the CLI's words when the state
    // it reaches holds NaN/Inf (the state stays readable; advancing further is refused).
    void advance_to(double t);
    double time() const;
    const Scene& scene() const { return scene_; }
    std::string backend() const { return backend_; }
    std::size_t size() const { return initial_size_; }

    const ParticleState<double>& state();  // read at the current time (cached until the next advance)
    pybind11::dict metrics();
    pybind11::dict stats() const;
    pybind11::dict provenance() const;

private:
    void advance_in_chunks(double t);
    void check_finite();        // after advancing: the CLI run's refusal of a NaN/Inf state
    void check_idle() const;    // not advancing in another thread
    void check_usable() const;  // idle, and the solver has not failed

    Scene scene_;
    std::string backend_;
    std::unique_ptr<Solver> solver_;
    std::size_t initial_size_ = 0;
    ParticleState<double> state_;
    bool state_current_ = false;
    Metrics metrics_;             // of state_, when metrics_current_
    bool metrics_current_ = false;
    bool busy_ = false;    // advance_to is running with the GIL released (another thread may call in)
    std::string failure_;  // set when the solver threw mid-step: its state is then unknown
    std::string nonfinite_;  // set when the state reached NaN/Inf: readable, but no way on
    double last_finite_time_ = 0;  // the latest time the state was seen finite
};

pybind11::dict stats_dict(const SolverStats& stats);
pybind11::dict metrics_dict(const Metrics& m);
// A run's metric series, one read-only NumPy array per column (int64 for the counts).
pybind11::dict metric_series_dict(const std::vector<Metrics>& series);

}  // namespace collide::python
