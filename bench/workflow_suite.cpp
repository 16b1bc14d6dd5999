// Suite `workflow`: the two commands a user waits for, timed as the user sees them, whole
// processes from start to exit:
//   1. `collide validate validation/suites/default.toml --jobs 2` (target: under 60 s),
//   2. `collide report` on its results (target: under 10 s),
// each run `--runs` times (default 3) into a fresh temporary directory; the median is judged
// against the target (the machine's speed drifts from hour to hour, so one run proves little).
// With --quick a two-scene suite written here stands in for the default one: a smoke test of
// the suite itself, whose times are not judged.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_suite.h"
#include "core/io/output_file.h"
#include "core/numerics/median.h"

namespace collide::bench {
namespace {

namespace fs = std::filesystem;

struct Workflow {
    std::string name;  // "validate" or "report"
    double target_seconds;
};

// Runs this program with `args`, its output appended to `log`; throws naming the log when it
// fails (a benchmark of a failing command would time its error path).
void run_this_program(const std::vector<std::string>& args, const std::string& log) {
    std::vector<char*> argv;
    static char self[] = "/proc/self/exe";
    argv.push_back(self);
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    // The log through the output guard (core/io/output_file.h), appended to by every run.
    const int out = open_output_stream(log, StreamStart::as_it_is);
    ::fcntl(out, F_SETFL, O_APPEND);
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(out);
        throw std::runtime_error("workflow: cannot start a process");
    }
    if (pid == 0) {
        ::dup2(out, STDOUT_FILENO), ::dup2(out, STDERR_FILENO);
        ::execv("/proc/self/exe", argv.data());
        ::_exit(127);
    }
    ::close(out);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("workflow: `collide " + args.front() + "` failed; its output is in " + log);
}

// A two-scene suite for --quick (the smoke test): step and event on two disks.
std::string write_quick_suite(const std::string& dir, const std::string& scene_dir) {
    const std::string path = dir + "/quick.toml";
    std::ostringstream text;
    text << "name = \"workflow-quick\"\nbackends = [\"step\"]\nreference = \"event\"\nseeds = [1]\n"
            "warmup_fraction = 0\n\n[[scene]]\nname = \"head_on_equal\"\npath = \""
         << scene_dir << "/head_on_equal.toml\"\n\n[[scene]]\nname = \"glancing\"\npath = \""
         << scene_dir << "/glancing.toml\"\n";
    write_file_atomically(path, text.str());
    return path;
}

std::string seconds_text(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", s);
    return buf;
}

// "validate ...: target: under 60 s (median of 3 runs); measured: 75.1, 77.0, 80.2 s, median 77.0 s; not met"
void judge(const Workflow& w, const std::string& command, const std::vector<double>& seconds, bool quick,
           BenchReport& report) {
    std::string runs;
    for (double s : seconds) runs += (runs.empty() ? "" : ", ") + seconds_text(s);
    const double m = median(seconds);
    const std::string verdict = quick ? "not judged (--quick runs a smaller suite)" : m < w.target_seconds ? "met" : "not met";
    report.note(command + ": target: under " + seconds_text(w.target_seconds) + " s (median of " +
                std::to_string(seconds.size()) + " runs); measured: " + runs + " s, median " + seconds_text(m) +
                " s; " + verdict);
    report.add({{"measure", w.name}, {"runs", std::int64_t(seconds.size())}, {"median_seconds", m},
                {"target_seconds", w.target_seconds}, {"met", std::string(quick ? "not judged" : m < w.target_seconds ? "yes" : "no")}});
}

}  // namespace

void run_workflow_suite(const BenchArgs& args, BenchReport& report) {
    const int runs = args.runs > 0 ? args.runs : 3;
    const std::string dir = [&] {
        const std::string base = (fs::temp_directory_path() / "collide-workflow-XXXXXX").string();
        std::vector<char> name(base.begin(), base.end());
        name.push_back('\0');
        if (!::mkdtemp(name.data())) throw std::runtime_error("workflow: cannot make a temporary directory");
        return std::string(name.data());
    }();
    const std::string suite = args.quick ? write_quick_suite(dir, args.scene_dir) : args.suite_dir + "/default.toml";
    const Workflow validate{"validate", 60}, render{"report", 10};
    std::vector<double> validate_seconds, report_seconds;
    report.expect_work(2.0 * runs);
    try {
        for (int k = 0; k < runs; ++k) {
            const std::string out = dir + "/results-" + std::to_string(k);
            const std::string log = dir + "/log-" + std::to_string(k) + ".txt";
            validate_seconds.push_back(
                time_seconds([&] { run_this_program({"validate", suite, "--jobs", "2", "--out", out}, log); }));
            report.work_done(1, "validate run " + std::to_string(k + 1) + " of " + std::to_string(runs) + ": " +
                                    seconds_text(validate_seconds.back()) + " s");
            report_seconds.push_back(time_seconds([&] { run_this_program({"report", out}, log); }));
            report.work_done(1, "report run " + std::to_string(k + 1) + " of " + std::to_string(runs) + ": " +
                                    seconds_text(report_seconds.back()) + " s");
            report.add({{"measure", "run"}, {"run", std::int64_t(k + 1)}, {"validate_seconds", validate_seconds.back()},
                        {"report_seconds", report_seconds.back()}, {"suite", suite}});
            fs::remove_all(out);
        }
    } catch (...) {
        std::fprintf(stderr, "workflow: the runs' output is kept in %s\n", dir.c_str());
        throw;
    }
    judge(validate, "collide validate " + suite + " --jobs 2", validate_seconds, args.quick, report);
    judge(render, "collide report (on those results)", report_seconds, args.quick, report);
    fs::remove_all(dir);
}

}  // namespace collide::bench
