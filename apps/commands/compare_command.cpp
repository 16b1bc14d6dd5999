// `collide compare DIR_A DIR_B [--sigma K] [--allow N]`: two result directories of the same
// suite side by side (validation/report/compare.py does the work): checks that changed status,
// observables that moved beyond their combined error bars, bit-identical cases. Exit status 1
// on a significant regression, for a user's own CI (docs/your-solver.md).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>

#include "apps/input_paths.h"
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
    std::fflush(stdout);
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        ::execl(COLLIDE_PYTHON, COLLIDE_PYTHON, script.c_str(), args.dir_a.c_str(), args.dir_b.c_str(), "--sigma",
                sigma.c_str(), "--allow", allow.c_str(), static_cast<char*>(nullptr));
        std::perror(COLLIDE_PYTHON);
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    // 1: a regression, listed above; 2: the directories cannot be compared, named above.
    if (WIFEXITED(status) && (WEXITSTATUS(status) == 1 || WEXITSTATUS(status) == 2)) throw CLI::RuntimeError(WEXITSTATUS(status));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error(std::string("the comparison failed (") + COLLIDE_PYTHON + " " + script + ")");
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
