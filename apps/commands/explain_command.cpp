// `collide explain DIR CASE_ID [--from T0] [--to T1] [--suite FILE] [--json]`: reruns one case
// of a finished suite (validation/explain/case_replay.h), checks that the rerun retraces the recorded run
// (its start bit for bit, its kinetic energy at the last output time before T0), then steps it
// one dt at a time and names the step in which the energy changed most, the disks it changed and
// the kind of contact behind it (validation/explain/energy_jump.h). The report calls it for every energy
// jump it shows (validation/explain/explain_case.h, docs/reading-a-report.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/io/input_file.h"
#include "core/text/printable.h"
#include "core/io/progress_line.h"
#include "apps/input_paths.h"
#include "core/metrics.h"
#include "commands.h"
#include "validation/explain/explain_case.h"

namespace collide::cli {
namespace {

struct ExplainArgs {
    std::string dir, case_id, suite;
    double from = 0, to = -1;
    bool json = false;
    std::vector<SceneOverride> overrides;
    SolverArgs solvers;  // outside solvers the run had on its command line, not in its suite file
};

// The suite file the results came from, as summary.json records it (or --suite).
std::string suite_of(const ExplainArgs& args) {
    if (!args.suite.empty()) return args.suite;
    const std::string path = args.dir + "/summary.json";
    std::string text;
    try {  // the input guard (core/io/input_file.h): a FIFO or a device is refused, not waited on
        text = read_input_file(path, max_text_input_bytes);
    } catch (const InputFileError& e) {
        throw std::runtime_error(path + ": " + e.cause() + "; expected the output directory of `collide validate`");
    }
    try {
        return nlohmann::json::parse(text).at("suite_file").get<std::string>();
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path + ": no suite_file to rebuild the case from (" + std::string(e.what()) +
                                 "); name the suite with --suite");
    }
}

void print_text(const validation::ReplayedCase& c, const validation::EnergyJump& jump) {
    std::printf("case      %s (%s, dt = %g)\n", printable(c.spec.id).c_str(), printable(c.spec.backend).c_str(),
                c.scene.run.dt);
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

void execute(const ExplainArgs& args) {
    // The outside solvers a suite file names ([solver.NAME]) replay too, one program call per step.
    validation::Suite loaded = validation::load_suite(suite_of(args));
    validation::add_solvers(loaded, solver_specs(args.solvers));
    const auto backends = validation::backends_with_solvers(loaded, all_backends(), python_runner());
    // A long case takes a while to reach --from and to search: a progress line with the time
    // left on a terminal, a plain line every 10 s in a log (core/io/progress_line.h).
    ProgressLine progress;
    const validation::ExplainedCase explained =
        validation::explain_case(args.dir, loaded, args.case_id, backends, args.overrides, args.from, args.to,
                                 [&progress](double t, double t_end) { progress.update_time(t, t_end); });
    progress.finish();
    if (args.json)
        std::printf("%s\n", validation::explanation_json(explained).dump(2).c_str());
    else
        print_text(explained.replayed, explained.jump);
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
    add_solver_options(*cmd, args->solvers);
    cmd->callback([args] { execute(*args); });
}

}  // namespace collide::cli
