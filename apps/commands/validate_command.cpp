// `collide validate SUITE [--out DIR] [--jobs N] [--resume] [--gather-hdf5] [--plan] [--solver NAME=COMMAND]`: runs a validation
// suite (validation/suites/*.toml), one case per core unless --jobs says otherwise, on every
// backend it names and writes DIR/summary.json,
// DIR/junit.xml and one HDF5 file per case. Exit status 1 when any check fails. Under mpirun
// or srun the cases are shared across the ranks (docs/scaling.md).
#include <unistd.h>

#include <cstdio>
#include <map>
#include <memory>

#include "apps/input_paths.h"
#include "commands.h"
#include "core/backend_registry.h"
#include "core/text/printable.h"
#include "validation/suite_runner.h"

namespace collide::cli {
namespace {

struct ValidateArgs {
    std::string suite_path;
    std::string out = "results";
    int jobs = 0;  // 0: not given; one case per core (MPI: one per rank)
    bool resume = false;
    bool gather_hdf5 = false;
    bool plan = false;
    SolverArgs solvers;
};

// CLI::PositiveNumber would say "not in range 0 to 1.8e308" for --jobs 0.
const CLI::Validator at_least_one_job(
    [](std::string& text) -> std::string {
        int jobs = 0;
        if (!CLI::detail::lexical_cast(text, jobs) || jobs < 1)
            return text + " is no number of jobs: expected a whole number >= 1 (the cases run at the same time)";
        return "";
    },
    "N >= 1");

// --plan: the cases the suite would run, per backend, after every check that needs no run;
// nothing runs and nothing is written. A suite file that cannot run fails here in a second.
void print_plan(const validation::Suite& suite, const std::vector<BackendInfo>& backends) {
    const auto specs = validation::plan_suite(suite, backends);
    std::map<std::string, std::size_t> per_backend;
    for (const auto& spec : specs) ++per_backend[spec.backend];
    std::printf("suite     %s: %zu cases planned on %zu scenes; nothing run\n", printable(suite.name).c_str(),
                specs.size(), suite.scenes.size());
    for (const auto& [backend, count] : per_backend) std::printf("backend   %-16s %zu cases\n", backend.c_str(), count);
}

void execute(const ValidateArgs& args) {
    // --- MPI hook (docs/scaling.md): under mpirun or srun the ranks share the cases out and
    // rank 0 alone reports; a plain run gets no dispatch and never initialises MPI.
    // Under MPI the ranks are the parallelism, so a rank runs one case at a time unless told.
    const auto dispatch = validation::start_case_dispatch(args.jobs > 0 ? args.jobs : 1, args.gather_hdf5);
    const bool reports = !dispatch || dispatch->is_root();
    // --- end of the MPI hook
    validation::Suite suite = validation::load_suite(args.suite_path);
    validation::add_solvers(suite, solver_specs(args.solvers));
    const auto backends = validation::backends_with_solvers(suite, all_backends(), python_runner());
    if (args.plan) {  // under MPI, once (rank 0)
        if (reports) print_plan(suite, backends);
        return;
    }
    validation::RunnerOptions options;
    options.output_dir = args.out;
    options.jobs = args.jobs > 0 ? args.jobs : dispatch ? 1 : validation::default_jobs();
    options.resume = args.resume;
    options.progress = reports ? stderr : nullptr;
    options.progress_is_terminal = ::isatty(STDERR_FILENO) != 0;
    options.dispatch = dispatch.get();
    const auto outcome = validation::run_suite(suite, backends, options);
    if (!reports) return;
    std::printf("suite     %s: %zu cases (%zu run, %zu resumed) in %.1f s, %d at a time%s\n",
                printable(suite.name).c_str(), outcome.cases.size(), outcome.cases_run, outcome.cases_resumed,
                outcome.wall_seconds, outcome.jobs, dispatch ? " per rank" : "");
    std::printf("checks    %zu passed, %zu failed, %zu left out\n", outcome.count(validation::CheckStatus::pass),
                outcome.count(validation::CheckStatus::fail), outcome.count(validation::CheckStatus::left_out));
    // One line per failed check: its detail may quote a solver's output, whose line breaks and
    // escapes are shown as \xNN (printable) so that they cannot forge lines of this summary.
    for (const auto& c : outcome.checks)
        if (c.status == validation::CheckStatus::fail)
            std::printf("FAIL      %s: %s: %s\n", printable(c.subject).c_str(), printable(c.check).c_str(),
                        printable(c.detail).c_str());
    std::printf("output    %s/summary.json, %s/junit.xml\n", args.out.c_str(), args.out.c_str());
    if (suite.stability) {
        // A stability suite's product is the classification: breaking cases are findings.
        // It fails only where something unexpected happened (validation/judge/stability.h).
        const auto unexpected = validation::unexpected_outcomes(outcome.cases, outcome.classifications);
        for (const auto& line : unexpected) std::printf("UNEXPECTED %s\n", printable(line).c_str());
        std::printf("stability %zu cases classified, %zu unexpected%s\n", outcome.classifications.size(),
                    unexpected.size(), unexpected.empty() ? " (failed checks above are findings of the map)" : "");
        if (!unexpected.empty()) throw CLI::RuntimeError(1);
        return;
    }
    if (!outcome.passed()) throw CLI::RuntimeError(1);  // exit status 1, the summary above says why
}

}  // namespace

void add_validate_command(CLI::App& app) {
    auto args = std::make_shared<ValidateArgs>();
    auto* cmd = app.add_subcommand("validate", "Run a validation suite; write summary.json, junit.xml and HDF5 per case");
    cmd->add_option("suite", args->suite_path, "Suite file (validation/suites/*.toml)")->required()->check(readable_file());
    cmd->add_option("-o,--out", args->out, "Output directory")->capture_default_str();
    cmd->add_option("-j,--jobs", args->jobs,
                    "Cases run at the same time, each in its own process (default: one per core; under MPI one per rank)")
        ->check(at_least_one_job);
    cmd->add_flag("--resume", args->resume, "Keep the cases that already have a result in the output directory");
    cmd->add_flag("--gather-hdf5", args->gather_hdf5,
                  "Under MPI: copy every rank's per-case HDF5 files into rank 0's output directory");
    cmd->add_flag("--plan", args->plan,
                  "Check the suite, its scenes and every case's settings, and print the cases per backend; run and write nothing");
    add_solver_options(*cmd, args->solvers);
    cmd->callback([args] { execute(*args); });
}

}  // namespace collide::cli
