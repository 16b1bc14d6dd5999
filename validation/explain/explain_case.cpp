#include "validation/explain/explain_case.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "core/io/shell_quote.h"
#include "core/metrics.h"

namespace collide::validation {

std::optional<IntervalJump> largest_interval_jump(const MetricSeries& series, double threshold, double factor) {
    if (series.size() < 3) return std::nullopt;
    double scale = 1e-300;
    for (const Metrics& m : series) scale = std::max(scale, std::fabs(m.kinetic_energy));
    std::vector<double> steps;
    for (std::size_t i = 1; i < series.size(); ++i) {
        const double change = (series[i].total_energy() - series[i - 1].total_energy()) / scale;
        if (!std::isfinite(change)) return std::nullopt;
        steps.push_back(change);
    }
    std::size_t largest = 0;  // the first of equal largest changes
    for (std::size_t i = 1; i < steps.size(); ++i)
        if (std::fabs(steps[i]) > std::fabs(steps[largest])) largest = i;
    std::vector<double> sizes(steps.size());
    std::transform(steps.begin(), steps.end(), sizes.begin(), [](double x) { return std::fabs(x); });
    std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(sizes.size() / 2), sizes.end());
    const double median = sizes[sizes.size() / 2];  // the upper median for an even count
    const double change = steps[largest];
    if (std::fabs(change) < threshold || std::fabs(change) < factor * median) return std::nullopt;
    return IntervalJump{series[largest].time, series[largest + 1].time, change, median, scale};
}

namespace {

// Where the replay is checked against the record before the search window: the last output
// time at or before it, the recorded kinetic energy there, and that time on the step grid.
struct PathCheck {
    double output_time;  // as the run recorded it (the time the metrics are computed at)
    double step_time;    // on the step grid: what the solver advances to
    double recorded_kinetic_energy;
};

// The check for a window that starts at t; none when no output time before t was recorded (then
// nothing is advanced before the window).
std::optional<PathCheck> path_check(const ReplayedCase& c, const CaseResult& record, double t) {
    const double interval = c.scene.run.output_interval, dt = c.scene.run.dt;
    const double output_time = std::floor(t / interval + 1e-9) * interval;
    if (output_time <= 0) return std::nullopt;
    const auto recorded = recorded_kinetic_energy(record, output_time);
    if (!recorded) return std::nullopt;
    return PathCheck{output_time, std::round(output_time / dt) * dt, *recorded};
}

// Advances the solver to the check's step time and compares its kinetic energy with the
// record's (relative 1e-9: the same code on the same input retraces the run).
void require_same_path(Solver& solver, const ReplayedCase& c, const PathCheck& check) {
    solver.advance_to(check.step_time);
    ParticleState<double> state;
    solver.read_state(state);
    const double k = compute_disk_metrics(c.scene, state, check.output_time).kinetic_energy;  // as the run recorded it
    const double recorded = check.recorded_kinetic_energy;
    if (!(std::fabs(k - recorded) <= 1e-9 * std::fabs(recorded)))
        throw std::runtime_error("case " + c.spec.id + ": the rerun does not retrace the recorded run (kinetic energy " +
                                 std::to_string(k) + " at t = " + std::to_string(check.output_time) + ", recorded " +
                                 std::to_string(recorded) + "); was the program or a file changed since the run?");
}

// The output times from `from` up to `start` (which ends the list), the replay's way to the
// search window: one advance per output interval, so that a long approach shows progress.
std::vector<double> approach_times(double from, double start, double interval) {
    std::vector<double> times;
    for (double t = from; t < start;) {
        t = std::min(start, (std::floor(t / interval + 1e-9) + 1) * interval);
        times.push_back(t);
    }
    return times;
}

// A case run by an outside solver that the suite file does not name (`validate --solver`,
// `--python-solver`, Python's solvers=) cannot be rebuilt from the suite file alone: say so, and
// how to name the solver again, instead of suggesting the suite file was edited.
void require_known_solver(const std::string& dir, const std::string& case_id, const std::vector<BackendInfo>& backends) {
    const std::string path = dir + "/cases/" + case_id + ".toml";
    if (!std::filesystem::is_regular_file(path)) return;  // replay_case says what is missing
    const CaseResult record = read_case_result(path);
    const std::string& name = record.spec.backend;
    if (std::any_of(backends.begin(), backends.end(), [&](const BackendInfo& b) { return b.name == name; })) return;
    const auto& p = record.provenance;
    const auto python = p.find("solver_python_class"), command = p.find("solver_command");
    if (command == p.end()) return;
    const std::string option = python != p.end() ? "--python-solver " + shell_quote(name + "=" + python->second)
                                                 : "--solver " + shell_quote(name + "=" + command->second);
    throw std::runtime_error("case " + case_id + " ran on the outside solver '" + name +
                             "', which the suite file does not name (it was given to `collide validate` on the "
                             "command line); name it again: collide explain " + shell_quote(dir) + " " + case_id + " " + option);
}

}  // namespace

ExplainedCase explain_case(const std::string& dir, const Suite& suite, const std::string& case_id,
                           const std::vector<BackendInfo>& backends, const std::vector<SceneOverride>& overrides,
                           double from, double to, const std::function<void(double, double)>& on_progress) {
    require_known_solver(dir, case_id, backends);
    ReplayedCase c = replay_case(suite, case_id, backends, overrides);
    if (c.backend.exact)  // exact: from collision to collision
        throw std::runtime_error("case " + c.spec.id + " ran on '" + c.backend.name +
                                 "', which has no time steps to look inside");
    const CaseResult record = read_case_result(dir + "/cases/" + c.spec.id + ".toml");
    // With overrides the case is a what-if: it starts and runs otherwise than the record.
    const bool what_if = !overrides.empty();
    if (!what_if) require_same_start(c, record);
    const double dt = c.scene.run.dt, end = to < 0 ? c.scene.run.duration : to;
    if (!(from >= 0) || !(end <= c.scene.run.duration + 0.5 * dt) || !(end > from))
        throw std::runtime_error("--from " + std::to_string(from) + " --to " + std::to_string(end) +
                                 ": expected 0 <= from < to <= the case's duration " + std::to_string(c.scene.run.duration));
    auto solver = c.backend.create(c.options);
    solver->load(c.scene, c.initial);
    const double start = std::floor(from / dt + 1e-9) * dt;
    const std::optional<PathCheck> check = what_if ? std::nullopt : path_check(c, record, start);
    const std::vector<double> approach = approach_times(check ? check->step_time : 0, start, c.scene.run.output_interval);
    // Every time the replay will stop at, announced first: an outside solver then runs them all in
    // one program call from t = 0, as the recorded run did (a call per step would start Node and
    // the engine each time, and an engine restarted from a state has lost its contact history).
    std::vector<double> planned;
    if (check) planned.push_back(check->step_time);
    for (const double t : approach) planned.push_back(t);
    for (const double t : step_times(start, dt, end)) planned.push_back(t);
    solver->plan_outputs(planned);
    if (check) require_same_path(*solver, c, *check);
    for (const double t : approach) {
        solver->advance_to(t);
        if (on_progress) on_progress(t, end);
    }
    EnergyJump jump = largest_energy_change(*solver, c.scene, end, on_progress);
    return ExplainedCase{std::move(c), std::move(jump)};
}

nlohmann::json explanation_json(const ExplainedCase& explained) {
    const ReplayedCase& c = explained.replayed;
    const EnergyJump& jump = explained.jump;
    nlohmann::json groups = nlohmann::json::array();
    for (const auto& g : jump.groups) {
        nlohmann::json disks = nlohmann::json::array(), pairs = nlohmann::json::array(), walls = nlohmann::json::array();
        nlohmann::json stones = nlohmann::json::array();
        for (const auto& d : g.disks)
            disks.push_back({{"index", d.index}, {"energy_before", d.energy_before}, {"energy_after", d.energy_after}});
        for (const auto& [i, j] : g.pairs) pairs.push_back({i, j});
        for (const auto& [i, w] : g.walls) walls.push_back({{"disk", i}, {"wall", w}});
        for (const auto& [i, st] : g.stones) stones.push_back({{"disk", i}, {"stone", st}});
        groups.push_back({{"kind", g.kind}, {"energy_change", g.energy_change}, {"disks", disks},
                          {"pairs", pairs}, {"walls", walls}, {"stones", stones}});
    }
    return {{"case", c.spec.id}, {"backend", c.spec.backend}, {"dt", c.scene.run.dt}, {"set", c.scene.overrides},
            {"step", jump.step},
            {"time_before", jump.time_before}, {"time_after", jump.time_after},
            {"kinetic_before", jump.kinetic_before}, {"energy_change", jump.energy_change},
            {"nonfinite", jump.nonfinite}, {"groups", groups}, {"description", describe(jump)}};
}

}  // namespace collide::validation
