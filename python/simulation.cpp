#include "simulation.h"

#include <chrono>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <pybind11/stl.h>

#include "core/scene/backend_table.h"
#include "core/run_driver.h"
#include "core/io/run_schema.h"
#include "core/scene/scene_loader.h"
#include "core/numerics/state_hash.h"
#include "core/numerics/target_time.h"
#include "core/scene/toml_fields.h"
#include "scene_from_dict.h"

namespace collide::python {

namespace py = pybind11;

namespace {

// Keyword values are read as TOML values, under Scene.from_dict's rules (so that, e.g.,
// threads=2**70 is refused naming "threads"), and then checked as the CLI or a file's key.
int threads_option(const py::handle& value) {
    const auto node = toml_value_from_python(value, "threads");
    const auto* n = node->as_integer();
    if (!n) throw py::type_error("threads = " + toml_value_text(*node) + ": expected an integer (0: all cores)");
    if (n->get() < INT_MIN || n->get() > INT_MAX)
        throw py::value_error("threads = " + toml_value_text(*node) + ": expected a thread count that fits in an int");
    return int(n->get());  // a negative count is refused by the backends that use it, as on the CLI
}

std::string text_option(const std::string& key, const py::handle& value) {
    const auto node = toml_value_from_python(value, key);
    if (const auto* s = node->as_string()) return s->get();
    if (key == "device" && node->is_integer()) return toml_value_text(*node);  // --cl-device 0
    throw py::type_error(key + " = " + toml_value_text(*node) + ": expected a string");
}

// A key of the scene's [backend.NAME] table, checked as the scene reader checks a file's.
void set_table_option(Scene& scene, const std::string& backend, const std::string& key, const py::handle& value) {
    const auto node = toml_value_from_python(value, key);
    const std::string name = "[backend." + backend + "]." + key + " = " + toml_value_text(*node);
    if (const std::string problem = backend_key_problem(backend, key); !problem.empty())
        throw py::value_error(name + ": expected " + problem);
    const auto text = backend_value_text(*node);
    if (!text) throw py::value_error(name + ": expected " + std::string(backend_value_expected));
    scene.backend_options[backend][key] = *text;
    scene.backend_option_origins[backend].erase(key);  // (not the file's value any more)
}

}  // namespace

BackendOptions backend_options(const py::kwargs& options, const std::string& backend, Scene& scene) {
    const std::string name = find_backend(backend).name;  // an unknown backend is named first
    BackendOptions o;
    for (const auto& [k, v] : options) {
        const std::string key = k.cast<std::string>();
        if (v.is_none()) continue;
        if (key == "threads") o.threads = threads_option(v);
        else if (key == "real") o.real = text_option(key, v);
        else if (key == "device") o.device = text_option(key, v);
        else set_table_option(scene, name, key, v);
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

// One entry per column of the run schema (core/io/run_schema.h), with the column's type, and
// total_energy = kinetic_energy + potential_energy.
py::dict metrics_dict(const Metrics& m) {
    py::dict d;
    for (const MetricColumn& column : metric_columns) {
        if (column.integer()) d[column.name] = m.*column.count;
        else d[column.name] = m.*column.real;
    }
    d["total_energy"] = m.total_energy();
    return d;
}

py::dict metric_series_dict(const std::vector<Metrics>& series) {
    auto read_only = [](auto&& values) {
        using T = typename std::decay_t<decltype(values)>::value_type;
        py::array_t<T> a(py::ssize_t(values.size()), values.data());  // copies
        mark_read_only(a);
        return a;
    };
    py::dict d;
    for (const MetricColumn& column : metric_columns) {
        if (column.integer()) {
            std::vector<std::int64_t> v;
            for (const Metrics& m : series) v.push_back(m.*column.count);
            d[column.name] = read_only(v);
        } else {
            std::vector<double> v;
            for (const Metrics& m : series) v.push_back(m.*column.real);
            d[column.name] = read_only(v);
        }
    }
    std::vector<double> total;
    for (const Metrics& m : series) total.push_back(m.total_energy());
    d["total_energy"] = read_only(total);
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
    {
        py::gil_scoped_release release;  // loading a big scene (OpenCL build, event queue) takes a while
        solver_->load(scene_, initial);
    }
    check_finite();  // the CLI's check at t = 0: a backend's own number type may not hold the scene
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

void Simulation::advance_to(double t) {
    check_usable();
    if (!nonfinite_.empty())
        throw std::runtime_error(nonfinite_ + "; this simulation cannot go on (its state is still readable)");
    // The one target-time check (core/numerics/target_time.h), before any work: a NaN, an infinity or a
    // time beyond the cap would otherwise start an endless loop below. Rounded to whole steps
    // here for every backend; the event solver checks its exact time again itself.
    check_target_time(backend_, t, solver_->time(), scene_.run.dt, true);
    state_current_ = metrics_current_ = false;
    advance_in_chunks(t);
    check_finite();
}

// Chunks end on whole time steps k dt: the stepped backends then take exactly the steps one
// call would (they step to round(t / dt)), and the event solver processes the same events in
// the same order whatever the times it is asked to stop at, so the pieces do not change the
// result. A chunk doubles while it takes under 50 ms, so Ctrl-C answers within about 0.1 s.
void Simulation::advance_in_chunks(double t) {
    const double dt = scene_.run.dt;
    std::int64_t step = std::llround(solver_->time() / dt), chunk = 1;
    busy_ = true;
    struct Done {
        bool& busy;
        ~Done() { busy = false; }  // runs with the GIL held again (the release scopes ended)
    } done{busy_};
    try {
        while (t >= solver_->time() && double(step + chunk) * dt < t) {
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

// As `collide run` stops at an output time whose state or metrics hold NaN/Inf, with its words
// (core/run_driver.h): a state that has lost its numbers cannot recover, and metrics() would
// report sums over the finite disks only (a kinetic energy of 0 beside nonfinite = 2). The
// metrics computed for the check are kept for metrics().
void Simulation::check_finite() {
    metrics_ = compute_metrics(scene_, state(), solver_->time());
    metrics_current_ = true;
    nonfinite_ = nonfinite_problem(backend_, state_, metrics_, last_finite_time_, "advancing in smaller pieces");
    if (!nonfinite_.empty()) throw std::runtime_error(nonfinite_);
    last_finite_time_ = metrics_.time;
}

const ParticleState<double>& Simulation::state() {
    check_usable();
    if (!state_current_) {
        solver_->read_state(state_);
        state_current_ = true;
    }
    return state_;
}

py::dict Simulation::metrics() {
    if (!metrics_current_) metrics_ = compute_metrics(scene_, state(), time());  // after a Ctrl-C
    metrics_current_ = true;
    return metrics_dict(metrics_);
}

py::dict Simulation::stats() const {
    check_idle();
    return stats_dict(solver_->stats());
}

py::dict Simulation::provenance() const {
    check_idle();
    return py::cast(solver_->provenance());
}

}  // namespace collide::python
