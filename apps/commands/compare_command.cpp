// `collide compare DIR_A DIR_B [--sigma K] [--allow N]`: two result directories of the same
// suite side by side (validation/report/compare.py does the work): checks that changed status,
// observables that moved beyond their combined error bars, bit-identical cases. Exit status 1
// on a significant regression, for a user's own CI (docs/your-solver.md).

#include <cstdio>
#include <memory>
#include <string>

#include "apps/input_paths.h"
#include "apps/python_script.h"
#include "apps/resource_path.h"
#include "commands.h"

namespace collide::cli {
namespace {

struct CompareArgs {
    std::string dir_a, dir_b;
    double sigma = 3;
    int allow = 0;
};

void execute(const CompareArgs& args) {
    const std::string script = resource_path("validation/report") + "/compare.py";
    const std::string sigma = std::to_string(args.sigma), allow = std::to_string(args.allow);
    const int status = run_python_script(script, {args.dir_a, args.dir_b, "--sigma", sigma, "--allow", allow});
    // 1: a regression, listed above; 2: the directories cannot be compared, named above.
    if (status == 1 || status == 2) throw CLI::RuntimeError(status);
    if (status != 0)
        throw std::runtime_error(std::string("the comparison failed (") + python_interpreter() + " " + script + ")");
}

}  // namespace

void add_compare_command(CLI::App& app) {
    auto args = std::make_shared<CompareArgs>();
    auto* cmd = app.add_subcommand("compare", "Compare two `collide validate` result directories of the same suite; "
                                              "exit status 1 on a regression");
    cmd->add_option("dir_a", args->dir_a, "The results before (the baseline)")->required()->check(readable_directory());
    cmd->add_option("dir_b", args->dir_b, "The results after")->required()->check(readable_directory());
    cmd->add_option("--sigma", args->sigma, "An observable moved when it changed by more than this many combined "
                                            "standard errors")->capture_default_str()->check(CLI::PositiveNumber);
    cmd->add_option("--allow", args->allow, "Newly failing checks tolerated before exit status 1")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    cmd->callback([args] { execute(*args); });
}

}  // namespace collide::cli
