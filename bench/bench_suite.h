// Benchmark suites behind `collide bench`. A suite runs fixed, seeded scenarios headless and
// records one row per measurement; BenchReport prints the rows as a table and writes them as
// CSV plus a JSON file with the provenance of the build and machine.
//
// Performance claims in docs/ come from these suites, never from timed unit tests.
#pragma once

#include <algorithm>
#include <cstdint>
#include <ctime>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace collide {
class ProgressLine;
}

namespace collide::bench {

// Seconds of processor time used by this process (unlike wall-clock time, it does not count
// the time other programs on a loaded machine hold the core).
inline double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

struct BenchArgs {
    std::vector<std::string> backends;  // empty: every backend the suite applies to
    std::vector<std::int64_t> sizes;    // particle counts; empty: the suite's default ladder
    std::vector<int> threads;           // thread counts to try; empty: the suite's default
    int steps = 240;                    // timed steps of dt per scenario (ParticleBox's suite: 240 frames)
    bool quick = false;                 // smaller ladder, for smoke tests
    double max_seconds_per_case = 60;   // a case whose first frame exceeds this is stopped
    std::string scene_dir;              // the scene library (data/scenes), for suites that run its scenes
    std::string suite_dir;              // the validation suites (validation/suites), for `workflow`
    int runs = 0;                       // whole-command runs of `workflow`; 0: its default (3)
};

// Whether `backend` should run: --backend names it, or --backend was not given.
inline bool wanted(const BenchArgs& args, const std::string& backend) {
    return args.backends.empty() || std::find(args.backends.begin(), args.backends.end(), backend) != args.backends.end();
}

using Value = std::variant<std::int64_t, double, std::string>;
using Row = std::map<std::string, Value>;

class BenchReport {
public:
    explicit BenchReport(std::string suite);
    ~BenchReport();
    // Adds a row and prints it at once on stdout.
    void add(const Row& row);
    // Progress with the time left (core/io/progress_line.h, on stderr): a suite says how much
    // work it plans, in its own unit (disk-steps, collisions), then how much is done as it
    // goes. The time left assumes the rest runs at the rate of the part done so far. In a log
    // (not a terminal) every call prints a line.
    void expect_work(double total);
    void work_done(double amount, const std::string& what);
    // Free-form notes ("box2d stopped at N = 1e5: one step took 1.3 s").
    void note(const std::string& text);
    const std::vector<Row>& rows() const { return rows_; }
    // Writes <prefix>.csv and <prefix>.json (rows + notes + provenance).
    void write(const std::string& prefix) const;

private:
    std::string suite_;
    std::vector<Row> rows_;
    std::vector<std::string> notes_;
    double work_total_ = 0, work_done_ = 0;
    std::unique_ptr<ProgressLine> progress_;  // made on the first work_done
};

struct BenchSuite {
    std::string name;
    std::string description;
    std::function<void(const BenchArgs&, BenchReport&)> run;
};

// Every suite compiled into this build (bench/all_suites.cpp).
const std::vector<BenchSuite>& all_bench_suites();

// Seconds of steady-clock time spent in f().
double time_seconds(const std::function<void()>& f);

}  // namespace collide::bench
