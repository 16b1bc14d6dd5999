// `collide report DIR`: renders DIR/report/index.html (self-contained, figures embedded) and
// DIR/report/summary.md from the results of `collide validate`, with the Python renderer in
// validation/report/ run by the interpreter CMake found (Debian's matplotlib, numpy, h5py).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "apps/resource_path.h"
#include "commands.h"
#include "validation/case_result.h"

namespace collide::cli {
namespace {

// Every case file the renderer will read must be complete: a truncated HDF5 file (a full
// disk, a copy cut short) is named here rather than drawn from, or failing deep in Python.
void check_case_files(const std::string& dir) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir + "/cases", error)) {
        if (entry.path().extension() != ".toml") continue;
        const std::string problem =
            validation::case_files_problem(validation::read_case_result(entry.path().string()), dir);
        if (!problem.empty())
            throw std::runtime_error(problem + "; run `collide validate ... --resume` to run that case again");
    }
}

void execute(const std::string& dir) {
    if (!std::filesystem::exists(dir + "/summary.json"))
        throw std::runtime_error(dir + "/summary.json: not found; expected the output directory of `collide validate`");
    check_case_files(dir);
    const std::string script = resource_path("validation/report") + "/make_report.py";
    // fork + exec (not system()): no shell, so directory names need no quoting.
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        // The renderer calls this program back (`collide render` for motion strips, `collide
        // explain` for energy jumps): tell it which one, unless the caller chose another.
        std::error_code error;
        const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
        if (!error) ::setenv("COLLIDE_EXECUTABLE", self.c_str(), 0);
        ::execl(COLLIDE_PYTHON, COLLIDE_PYTHON, script.c_str(), dir.c_str(), static_cast<char*>(nullptr));
        std::perror(COLLIDE_PYTHON);
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    // Exit status 2: an input file is malformed; the renderer has named it and what is wrong.
    if (WIFEXITED(status) && WEXITSTATUS(status) == 2)
        throw std::runtime_error("no report written: " + dir + " holds a malformed input (named above)");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error(std::string("the report renderer failed (") + COLLIDE_PYTHON + " " + script + ")");
}

}  // namespace

void add_report_command(CLI::App& app) {
    auto dir = std::make_shared<std::string>();
    auto* cmd = app.add_subcommand("report", "Render DIR/report/index.html and summary.md from `collide validate` results");
    cmd->add_option("dir", *dir, "Output directory of `collide validate`")->required()->check(CLI::ExistingDirectory);
    cmd->callback([dir] { execute(*dir); });
}

}  // namespace collide::cli
