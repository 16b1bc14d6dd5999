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
#include "core/scene.h"

namespace collide::python {

// Backend options from Python keywords: threads, real, device; every other keyword goes to
// BackendOptions::extra as text (the backend validates it).
BackendOptions backend_options(const pybind11::kwargs& options);

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
    void check_idle() const;    // not advancing in another thread
    void check_usable() const;  // idle, and the solver has not failed

    Scene scene_;
    std::string backend_;
    std::unique_ptr<Solver> solver_;
    std::size_t initial_size_ = 0;
    ParticleState<double> state_;
    bool state_current_ = false;
    bool busy_ = false;    // advance_to is running with the GIL released (another thread may call in)
    std::string failure_;  // set when the solver threw mid-step: its state is then unknown
};

pybind11::dict stats_dict(const SolverStats& stats);
pybind11::dict metrics_dict(const Metrics& m);

}  // namespace collide::python
