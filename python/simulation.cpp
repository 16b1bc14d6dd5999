#include "simulation.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <pybind11/stl.h>

#include "core/scene_loader.h"
#include "core/state_hash.h"

namespace collide::python {

namespace py = pybind11;

BackendOptions backend_options(const py::kwargs& options) {
    BackendOptions o;
    for (const auto& [k, v] : options) {
        const std::string key = k.cast<std::string>();
        if (key == "threads") o.threads = v.cast<int>();
        else if (key == "real") o.real = v.cast<std::string>();
        else if (key == "device") o.device = py::str(v).cast<std::string>();
        else o.extra[key] = py::str(v).cast<std::string>();
    }
    if (!o.real.empty() && o.real != "float" && o.real != "double")
        throw py::value_error("real = '" + o.real + "': expected 'float' or 'double'");
    return o;
}

const BackendInfo& backend_for(const Scene& scene, const std::string& name) {
    const BackendInfo& backend = find_backend(name);
    if (auto reason = backend.supports(scene))
        throw std::invalid_argument("backend '" + backend.name + "' cannot run scene '" + scene.name + "': " + *reason);
    return backend;
}

namespace {

void mark_read_only(py::array& a) { a.attr("flags").attr("writeable") = false; }

}  // namespace

py::array_t<double> read_only_pairs(const std::vector<double>& a, const std::vector<double>& b) {
    const auto n = py::ssize_t(a.size());
    py::array_t<double> out({n, py::ssize_t(2)});
    auto view = out.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i) {
        view(i, 0) = a[std::size_t(i)];
        view(i, 1) = b[std::size_t(i)];
    }
    mark_read_only(out);
    return out;
}

py::array_t<double> read_only_array(const std::vector<double>& a) {
    py::array_t<double> out(py::ssize_t(a.size()), a.data());  // copies
    mark_read_only(out);
    return out;
}

py::dict metrics_dict(const Metrics& m) {
    py::dict d;
    d["time"] = m.time;
    d["momentum_x"] = m.momentum_x;
    d["momentum_y"] = m.momentum_y;
    d["kinetic_energy"] = m.kinetic_energy;
    d["potential_energy"] = m.potential_energy;
    d["total_energy"] = m.total_energy();
    d["overlapping_pairs"] = m.overlapping_pairs;
    d["max_overlap"] = m.max_overlap;
    d["mean_overlap"] = m.mean_overlap;
    d["max_wall_penetration"] = m.max_wall_penetration;
    d["nonfinite"] = m.nonfinite;
    return d;
}

py::dict stats_dict(const SolverStats& s) {
    py::dict d;
    d["steps"] = s.steps;
    d["contacts"] = s.contacts;
    d["phase_seconds"] = py::cast(s.phase_seconds);
    d["counters"] = py::cast(s.counters);
    return d;
}

Simulation::Simulation(const Scene& scene, const std::string& backend, const BackendOptions& options)
    : scene_(scene) {
    const BackendInfo& info = backend_for(scene_, backend);
    backend_ = info.name;
    const ParticleState<double> initial = generate_initial_state(scene_);
    initial_size_ = initial.size();
    solver_ = info.create(options);
    py::gil_scoped_release release;  // loading a big scene (OpenCL build, event queue) takes a while
    solver_->load(scene_, initial);
}

void Simulation::check_idle() const {
    // The GIL is held here and wherever busy_ changes, so a plain bool is enough.
    if (busy_)
        throw std::runtime_error(backend_ + ": this simulation is advancing in another thread; wait for advance_to() to return");
}

void Simulation::check_usable() const {
    check_idle();
    if (!failure_.empty())
        throw std::runtime_error(backend_ + ": this simulation failed earlier and cannot go on (" + failure_ + ")");
}

double Simulation::time() const {
    check_idle();
    return solver_->time();
}

// Chunks end on whole time steps k dt: the stepped backends then take exactly the steps one
// call would (they step to round(t / dt)), and the event solver processes the same events in
// the same order whatever the times it is asked to stop at, so the pieces do not change the
// result. A chunk doubles while it takes under 50 ms, so Ctrl-C answers within about 0.1 s.
void Simulation::advance_to(double t) {
    check_usable();
    state_current_ = false;
    const double dt = scene_.run.dt;
    std::int64_t step = std::llround(solver_->time() / dt), chunk = 1;
    busy_ = true;
    struct Done {
        bool& busy;
        ~Done() { busy = false; }  // runs with the GIL held again (the release scopes ended)
    } done{busy_};
    try {
        while (std::isfinite(t) && t >= solver_->time() && double(step + chunk) * dt < t) {
            step += chunk;
            const auto start = std::chrono::steady_clock::now();
            {
                py::gil_scoped_release release;
                solver_->advance_to(double(step) * dt);
            }
            if (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(50) && chunk < (std::int64_t(1) << 40))
                chunk *= 2;
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        }
        py::gil_scoped_release release;
        solver_->advance_to(t);
    } catch (const py::error_already_set&) {
        throw;  // KeyboardInterrupt (or another signal handler's exception): the state is whole
    } catch (const std::invalid_argument&) {
        throw;  // refused before any work (a time in the past): the state is untouched
    } catch (const std::exception& e) {
        failure_ = e.what();
        throw;
    }
}

const ParticleState<double>& Simulation::state() {
    check_usable();
    if (!state_current_) {
        solver_->read_state(state_);
        state_current_ = true;
    }
    return state_;
}

py::dict Simulation::metrics() { return metrics_dict(compute_metrics(scene_, state(), time())); }

py::dict Simulation::stats() const {
    check_idle();
    return stats_dict(solver_->stats());
}

py::dict Simulation::provenance() const {
    check_idle();
    return py::cast(solver_->provenance());
}

}  // namespace collide::python
