// `collide explain DIR CASE_ID [--from T0] [--to T1] [--suite FILE] [--json]`: reruns one case
// of a finished suite (validation/explain/case_replay.h), checks that the rerun retraces the recorded run
// (its start bit for bit, its kinetic energy at the last output time before T0), then steps it
// one dt at a time and names the step in which the energy changed most, the disks it changed and
// the kind of contact behind it (validation/explain/energy_jump.h). The report calls it for every energy
// jump it shows (docs/reading-a-report.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/io/progress_line.h"
#include "apps/input_paths.h"
#include "core/metrics.h"
#include "commands.h"
#include "validation/explain/case_replay.h"
#include "validation/run/case_result.h"
#include "validation/explain/energy_jump.h"

namespace collide::cli {
namespace {

struct ExplainArgs {
    std::string dir, case_id, suite;
    double from = 0, to = -1;
    bool json = false;
    std::vector<SceneOverride> overrides;
};

// The suite file the results came from, as summary.json records it (or --suite).
std::string suite_of(const ExplainArgs& args) {
    if (!args.suite.empty()) return args.suite;
    const std::string path = args.dir + "/summary.json";
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": not found; expected the output directory of `collide validate`");
    try {
        return nlohmann::json::parse(in).at("suite_file").get<std::string>();
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path + ": no suite_file to rebuild the case from (" + std::string(e.what()) +
                                 "); name the suite with --suite");
    }
}

nlohmann::json to_json(const validation::ReplayedCase& c, const validation::EnergyJump& jump) {
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
            {"nonfinite", jump.nonfinite}, {"groups", groups}, {"description", validation::describe(jump)}};
}

void print_text(const validation::ReplayedCase& c, const validation::EnergyJump& jump) {
    std::printf("case      %s (%s, dt = %g)\n", c.spec.id.c_str(), c.spec.backend.c_str(), c.scene.run.dt);
    if (!c.scene.overrides.empty())
        std::printf("set       %s (a what-if rerun, not the recorded run)\n", c.scene.overrides.c_str());
    std::printf("step      %lld: t = %.6g -> %.6g\n", static_cast<long long>(jump.step), jump.time_before, jump.time_after);
    std::printf("change    energy %+.6g (kinetic energy before the step %.6g)\n", jump.energy_change,
                jump.kinetic_before);
    for (std::size_t k = 0; k < jump.groups.size() && k < 5; ++k) {
        const auto& g = jump.groups[k];
        std::printf("group %zu   %s: energy %+.6g\n", k + 1, g.kind.c_str(), g.energy_change);
        for (const auto& d : g.disks)
            std::printf("          disk %zu: %.6g -> %.6g\n", d.index, d.energy_before, d.energy_after);
        for (const auto& [i, j] : g.pairs) std::printf("          contact %zu-%zu\n", i, j);
        for (const auto& [i, w] : g.walls) std::printf("          disk %zu at the %s wall\n", i, w.c_str());
        for (const auto& [i, st] : g.stones) std::printf("          disk %zu at stone %zu\n", i, st);
    }
    if (jump.groups.size() > 5) std::printf("          (%zu more groups)\n", jump.groups.size() - 5);
    std::printf("in words  %s\n", validation::describe(jump).c_str());
}

// Advances the solver to the last output time at or before t and checks its kinetic energy
// against the record's (relative 1e-9: the same code on the same input retraces the run).
void require_same_path(Solver& solver, const validation::ReplayedCase& c, const validation::CaseResult& record,
                       double t) {
    const double interval = c.scene.run.output_interval, dt = c.scene.run.dt;
    const double check = std::floor(t / interval + 1e-9) * interval;
    const auto recorded = validation::recorded_kinetic_energy(record, check);
    if (!recorded) return;
    if (check > 0) solver.advance_to(std::round(check / dt) * dt);
    ParticleState<double> state;
    solver.read_state(state);
    const double k = compute_disk_metrics(c.scene, state, check).kinetic_energy;  // as the run recorded it
    if (!(std::fabs(k - *recorded) <= 1e-9 * std::fabs(*recorded)))
        throw std::runtime_error("case " + c.spec.id + ": the rerun does not retrace the recorded run (kinetic energy " +
                                 std::to_string(k) + " at t = " + std::to_string(check) + ", recorded " +
                                 std::to_string(*recorded) + "); was the program or a file changed since the run?");
}

void execute(const ExplainArgs& args) {
    // The outside solvers a suite file names ([solver.NAME]) replay too, one program call per step.
    const std::string suite = suite_of(args);
    const validation::Suite loaded = validation::load_suite(suite);
    const auto backends = validation::backends_with_solvers(loaded, all_backends(), python_runner());
    const validation::ReplayedCase c = validation::replay_case(loaded, args.case_id, backends, args.overrides);
    if (c.backend.name == "event" || c.backend.name == "event-plain")  // exact: from collision to collision
        throw std::runtime_error("case " + c.spec.id + " ran on '" + c.backend.name +
                                 "', which has no time steps to look inside");
    const validation::CaseResult record = validation::read_case_result(args.dir + "/cases/" + c.spec.id + ".toml");
    // With --set the case is a what-if: it starts and runs otherwise than the record.
    const bool what_if = !args.overrides.empty();
    if (!what_if) validation::require_same_start(c, record);
    const double dt = c.scene.run.dt, end = args.to < 0 ? c.scene.run.duration : args.to;
    if (!(args.from >= 0) || !(end <= c.scene.run.duration + 0.5 * dt) || !(end > args.from))
        throw std::runtime_error("--from " + std::to_string(args.from) + " --to " + std::to_string(end) +
                                 ": expected 0 <= from < to <= the case's duration " + std::to_string(c.scene.run.duration));
    auto solver = c.backend.create(c.options);
    solver->load(c.scene, c.initial);
    const double start = std::floor(args.from / dt + 1e-9) * dt;
    if (!what_if) require_same_path(*solver, c, record, start);
    // A long case takes a while to reach --from and to search: a progress line with the time
    // left on a terminal, a plain line every 10 s in a log (core/io/progress_line.h).
    ProgressLine progress;
    const double interval = c.scene.run.output_interval;
    for (double t = solver->time(); t < start;) {
        t = std::min(start, (std::floor(t / interval + 1e-9) + 1) * interval);
        solver->advance_to(t);
        progress.update_time(t, end);
    }
    const validation::EnergyJump jump = validation::largest_energy_change(
        *solver, c.scene, end, [&progress](double t, double t_end) { progress.update_time(t, t_end); });
    progress.finish();
    if (args.json)
        std::printf("%s\n", to_json(c, jump).dump(2).c_str());
    else
        print_text(c, jump);
}

}  // namespace

void add_explain_command(CLI::App& app) {
    auto args = std::make_shared<ExplainArgs>();
    auto* cmd = app.add_subcommand(
        "explain", "Rerun one case of `collide validate` results and name the step that changed the energy most, "
                   "its disks and the kind of contact");
    cmd->add_option("dir", args->dir, "Output directory of `collide validate`")->required()->check(readable_directory());
    cmd->add_option("case", args->case_id, "Case id (summary.json's cases[].id)")->required();
    cmd->add_option("--from", args->from, "Look at steps after this time (default 0)");
    cmd->add_option("--to", args->to, "... and up to this time (default: the case's duration)");
    cmd->add_option("--suite", args->suite, "Suite file (default: the one summary.json records)");
    cmd->add_flag("--json", args->json, "Print JSON instead of text");
    add_set_option(*cmd, args->overrides);
    cmd->callback([args] { execute(*args); });
}

}  // namespace collide::cli
