#include "core/run_driver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/thermo/pressure_record.h"

namespace collide {

std::vector<double> output_times(const Scene& scene) {
    const double interval = scene.run.output_interval, duration = scene.run.duration;
    const auto count = std::int64_t(std::llround(duration / interval));
    std::vector<double> times;
    for (std::int64_t k = 0; k <= count; ++k) times.push_back(std::min(duration, double(k) * interval));
    if (times.back() < duration) times.push_back(duration);
    return times;
}

namespace {

// "step: 3 disk(s) with NaN/Inf state at t = 0.5 (first: disk 17, x = (...), v = (...)); every
// disk was finite at t = 0.4: the state broke in between (a smaller [run] output_interval
// narrows it down)"
std::string describe_nonfinite(const std::string& solver_name, const ParticleState<double>& state,
                               std::int64_t count, double t, double last_finite_t, const std::string& narrower) {
    std::ostringstream msg;
    msg << solver_name << ": " << count << " disk(s) with NaN/Inf state at t = " << t;
    for (std::size_t i = 0; i < state.size(); ++i) {
        if (std::isfinite(state.x[i]) && std::isfinite(state.y[i]) && std::isfinite(state.vx[i]) &&
            std::isfinite(state.vy[i]))
            continue;
        msg << " (first: disk " << i << ", x = (" << state.x[i] << ", " << state.y[i] << "), v = ("
            << state.vx[i] << ", " << state.vy[i] << "))";
        break;
    }
    if (t <= last_finite_t)  // the first output: nothing ran yet that could have broken it
        msg << "; the backend's initial state already holds it (a value beyond the range of its "
               "number type, e.g. float's 3.4e38?)";
    else
        msg << "; every disk was finite at t = " << last_finite_t
            << ": the state broke in between (" << narrower << " narrows it down)";
    return msg.str();
}

// The first metric that is NaN or Inf although every disk is finite (an energy that overflows
// double with finite velocities, e.g. |v| = 1e200), or nullptr when all are finite.
const char* nonfinite_metric(const Metrics& m) {
    const std::pair<const char*, double> values[] = {
        {"kinetic energy", m.kinetic_energy}, {"potential energy", m.potential_energy},
        {"momentum x", m.momentum_x},         {"momentum y", m.momentum_y},
        {"max overlap", m.max_overlap},       {"mean overlap", m.mean_overlap},
        {"max wall penetration", m.max_wall_penetration}};
    for (const auto& [name, value] : values)
        if (!std::isfinite(value)) return name;
    return nullptr;
}

std::string describe_nonfinite_metric(const std::string& solver_name, const Metrics& m, const char* name) {
    std::ostringstream msg;
    msg << solver_name << ": NaN/Inf metric at t = " << m.time << ": the " << name
        << " is not finite (kinetic " << m.kinetic_energy << ", potential " << m.potential_energy
        << ", momentum (" << m.momentum_x << ", " << m.momentum_y
        << ")) although every disk is finite: the values overflow double (speeds, masses or gravity too large)";
    return msg.str();
}

}  // namespace

std::string nonfinite_problem(const std::string& solver_name, const ParticleState<double>& state, const Metrics& m,
                              double last_finite_t, const std::string& narrower) {
    if (m.nonfinite > 0) return describe_nonfinite(solver_name, state, m.nonfinite, m.time, last_finite_t, narrower);
    if (const char* name = nonfinite_metric(m)) return describe_nonfinite_metric(solver_name, m, name);
    return "";
}

namespace {

// solver.advance_to(t), its time added to result.wall_seconds.
void advance_timed(Solver& solver, double t, RunResult& result) {
    const auto start = std::chrono::steady_clock::now();
    solver.advance_to(t);
    result.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Advances from `from` to the output time `to`. With a pressure record, the interval is cut into
// `windows` equal windows, and the solver's statistics are sampled at the end of each (the
// event-driven solvers only process events up to each time, so the extra stops change nothing
// in the trajectory).
void advance_sampling(Solver& solver, double from, double to, std::size_t windows,
                      std::optional<PressureRecorder>& recorder, RunResult& result) {
    for (std::size_t w = 1; recorder && w < windows && to > from; ++w) {
        const double t = from + (to - from) * double(w) / double(windows);
        advance_timed(solver, t, result);
        recorder->sample(solver.stats(), t);
    }
    advance_timed(solver, to, result);
    if (recorder) recorder->sample(solver.stats(), to);
}

}  // namespace

RunResult run_scene(const Scene& scene, Solver& solver, const ParticleState<double>& initial,
                    const RunOptions& options) {
    RunResult result;
    solver.load(scene, initial);
    if (options.writer) options.writer->write_particles(initial);
    ParticleState<double> state;
    double last_finite_t = 0;  // the initial state is checked by the scene loader and the solver
    const std::vector<double> times = output_times(scene);
    solver.plan_outputs(times);
    // beta P d^2 of a periodic gas of equal disks from an event-driven solver (pressure_record.h).
    const std::size_t windows = pressure_windows_per_output(times.size() - 1);
    std::optional<PressureRecorder> recorder =
        pressure_recorder_for(scene, initial, solver, scene.run.output_interval / double(windows));
    double previous_t = times.front();
    for (double t : times) {
        advance_sampling(solver, previous_t, t, windows, recorder, result);
        previous_t = t;
        solver.read_state(state);
        if (recorder) recorder->observe(state);
        const Metrics m = compute_metrics(scene, state, t);
        result.series.push_back(m);
        if (options.writer) options.writer->append(m, state);
        if (options.on_state) options.on_state(state, m);
        if (options.on_output) options.on_output(t, scene.run.duration);
        if (options.stop_on_nonfinite)
            if (std::string problem = nonfinite_problem(solver.name(), state, m, last_finite_t,
                                                        "a smaller [run] output_interval");
                !problem.empty())
                throw std::runtime_error(problem);
        if (m.nonfinite == 0) last_finite_t = t;
    }
    result.final_state = std::move(state);
    result.stats = solver.stats();
    if (recorder)
        for (const auto& [name, value] : recorder->counters()) result.stats.counters[name] = value;
    if (options.writer) options.writer->write_stats(result.stats);
    return result;
}

}  // namespace collide
