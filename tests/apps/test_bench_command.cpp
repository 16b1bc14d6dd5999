// `collide bench` as a user runs it: the event-driven suite on small sizes writes a table whose
// columns hang together (median within the windows' range, ratio 1 at the smallest N, every
// timed collision counted), and bad arguments fail before anything runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/program_runner.h"
#include "tests/support/scratch_directory.h"

namespace collide {
namespace {

using test::contains;
using test::run_program;
using test::ScratchDirectory;

using CsvRow = std::map<std::string, std::string>;

// `collide bench ARGS... -o DIR/b`, run in the scratch directory DIR: its tables are
// DIR/b-SUITE.csv and .json.
test::ProgramResult run_bench(const ScratchDirectory& dir, std::vector<std::string> args) {
    args.insert(args.begin(), "bench");
    args.push_back("-o");
    args.push_back(dir.file("b"));
    return run_program(COLLIDE_EXECUTABLE, args, dir);
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string field; std::getline(s, field, ',');) fields.push_back(field);
    return fields;
}

std::vector<CsvRow> read_csv(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::vector<CsvRow> rows;
    if (!std::getline(in, line)) return rows;
    const std::vector<std::string> header = split(line);
    while (std::getline(in, line)) {
        const std::vector<std::string> fields = split(line);
        CsvRow row;
        for (std::size_t k = 0; k < header.size() && k < fields.size(); ++k) row[header[k]] = fields[k];
        rows.push_back(row);
    }
    return rows;
}

double number(const CsvRow& row, const std::string& column) {
    auto it = row.find(column);
    if (it == row.end()) {
        ADD_FAILURE() << "missing column " << column;
        return 0;
    }
    return std::stod(it->second);
}

TEST(BenchCommand, EventSuiteWritesAConsistentTablePerAreaFractionAndSize) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"event", "--quick", "--sizes", "600", "300"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(contains(result.err, "melting")) << "progress is reported: " << result.err;
    const std::vector<CsvRow> rows = read_csv(dir.file("b-event.csv"));
    ASSERT_EQ(rows.size(), 12u) << "3 area fractions x 2 sizes x 2 solvers (event, event-plain)";
    int plain_rows = 0;
    for (const CsvRow& row : rows) {
        const double n = number(row, "n"), ns = number(row, "ns_per_collision");
        SCOPED_TRACE(row.at("backend") + ", n = " + row.at("n") + ", area fraction " + row.at("area_fraction"));
        ASSERT_TRUE(row.at("backend") == "event" || row.at("backend") == "event-plain") << row.at("backend");
        // cost_vs_event: this solver's ns per collision over event's at the same N (1 for event).
        if (row.at("backend") == "event") {
            EXPECT_DOUBLE_EQ(number(row, "cost_vs_event"), 1.0);
        } else {
            ++plain_rows;
            EXPECT_GT(number(row, "cost_vs_event"), 0.0);
        }
        EXPECT_GE(number(row, "collisions"), 100000) << "--quick times at least 1e5 collisions";
        EXPECT_GT(ns, 0);
        EXPECT_LE(number(row, "ns_per_collision_min"), ns);
        EXPECT_GE(number(row, "ns_per_collision_max"), ns);
        EXPECT_NEAR(number(row, "collisions_per_second") * ns, 1e9, 1e9 * 1e-5);
        EXPECT_GE(number(row, "events_per_collision"), 1.0) << "every collision is an event";
        // Sizes are sorted: the ratio column is relative to the smallest N of the same solver and
        // area fraction.
        if (n == 300) {
            EXPECT_DOUBLE_EQ(number(row, "cost_vs_smallest_n"), 1.0);
        }
        // The ratio is a median of per-window ratios, inside their range.
        EXPECT_LE(number(row, "cost_vs_smallest_n_min"), number(row, "cost_vs_smallest_n"));
        EXPECT_GE(number(row, "cost_vs_smallest_n_max"), number(row, "cost_vs_smallest_n"));
    }
    EXPECT_EQ(plain_rows, 6);
    // The windows of the two sizes are timed in turn, so that a drifting machine speed
    // affects both alike: window 1 of N = 300, window 1 of N = 600, then window 2 of N = 300.
    const std::size_t first_small = result.err.find("timing window 1 of 5: N = 300 ");
    const std::size_t first_large = result.err.find("timing window 1 of 5: N = 600 ");
    const std::size_t second_small = result.err.find("timing window 2 of 5: N = 300 ");
    ASSERT_NE(first_small, std::string::npos) << result.err;
    ASSERT_NE(first_large, std::string::npos) << result.err;
    ASSERT_NE(second_small, std::string::npos) << result.err;
    EXPECT_LT(first_small, first_large);
    EXPECT_LT(first_large, second_small);
    // Each area fraction's targets of `event` are printed with the measured figure; sizes other
    // than the targets' are said to be so, not judged.
    EXPECT_TRUE(contains(result.out, "event, area fraction 0.5: target: >= 2e6 collisions/s at N = 1e5; measured: N = 1e5 not run"))
        << result.out;
    EXPECT_TRUE(contains(result.out, "event, area fraction 0.1: target: >= 1e6 collisions/s at N = 1e5"));
    EXPECT_TRUE(contains(result.out, "event, area fraction 0.7: target: cost per collision from N = 1e3 to 1e6 within 1.3x; "
                                     "measured: "));
    EXPECT_TRUE(contains(result.out, "(not the target's sizes: not judged)"));
    std::ifstream json(dir.file("b-event.json"));
    std::stringstream text;
    text << json.rdbuf();
    EXPECT_TRUE(contains(text.str(), "\"git_commit\"")) << "the JSON carries the build's provenance";
}

// The workflow suite times whole commands as a user runs them and judges each median against
// its target; --quick runs a two-scene suite and says its times are not judged.
TEST(BenchCommand, WorkflowTimesValidateAndReportAndPrintsEachTarget) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"workflow", "--quick", "--runs", "2"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const std::vector<CsvRow> rows = read_csv(dir.file("b-workflow.csv"));
    ASSERT_EQ(rows.size(), 4u);  // two runs, then the validate and report medians
    for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(rows[k].at("measure"), "run");
        EXPECT_GT(std::stod(rows[k].at("validate_seconds")), 0);
        EXPECT_GT(std::stod(rows[k].at("report_seconds")), 0);
    }
    EXPECT_EQ(rows[2].at("measure"), "validate");
    EXPECT_EQ(rows[2].at("target_seconds"), "60");
    EXPECT_EQ(rows[3].at("measure"), "report");
    EXPECT_EQ(rows[3].at("target_seconds"), "10");
    EXPECT_TRUE(contains(result.out, "target: under 60.0 s (median of 2 runs); measured: ")) << result.out;
    EXPECT_TRUE(contains(result.out, "target: under 10.0 s (median of 2 runs); measured: ")) << result.out;
    EXPECT_TRUE(contains(result.out, "not judged (--quick runs a smaller suite)")) << result.out;
}

// `--steps` is the count of timed steps (`run --frames` is a different thing: a switch that
// stores states); the JSON beside the CSV is valid JSON with the same rows and the provenance.
TEST(BenchCommand, StepsSetsTheTimedStepsAndTheJsonHoldsTheRows) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"throughput", "--quick", "--sizes", "500", "--backend", "step", "--steps",
                                         "3"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const std::vector<CsvRow> rows = read_csv(dir.file("b-throughput.csv"));
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(number(rows[0], "steps"), 3);
    std::ifstream in(dir.file("b-throughput.json"));
    const nlohmann::json json = nlohmann::json::parse(in);  // throws on invalid JSON
    EXPECT_EQ(json.at("suite"), "throughput");
    EXPECT_EQ(json.at("provenance").at("command_line").get<std::string>().find(COLLIDE_EXECUTABLE), 0u);
    ASSERT_EQ(json.at("rows").size(), 1u);
    EXPECT_EQ(json.at("rows")[0].at("steps"), 3);
    EXPECT_EQ(json.at("rows")[0].at("backend"), "step");
    EXPECT_EQ(json.at("rows")[0].at("n"), 500);
}

// The throughput suite times backends that step: an exact solver and a sampler, named with
// --backend, are left out with a note saying why (by what they claim, not by their names),
// and write no row; the stepped backend beside them does.
TEST(BenchCommand, ThroughputLeavesOutBackendsWithoutATimeStepAndSaysWhy) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"throughput", "--quick", "--sizes", "300", "--backend", "step", "event-plain",
                                         "metropolis", "--steps", "3"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const std::vector<CsvRow> rows = read_csv(dir.file("b-throughput.csv"));
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].at("backend"), "step");
    EXPECT_TRUE(contains(result.out, "event-plain left out: exact (event-driven), it has no time step")) << result.out;
    EXPECT_TRUE(contains(result.out, "metropolis left out: a sampler has no time and no time step")) << result.out;
}

// The bandwidth suite: the triad rows, the in-cache compute ceiling (one thread, times the
// threads) and the large run, whose fractions are consistent with its own columns, and the
// target's verdict line (here not the target's configuration: N = 2000).
TEST(BenchCommand, BandwidthSuitePrintsTheBoundTheComputeCeilingAndTheTargetsVerdict) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"bandwidth", "--quick", "--sizes", "2000", "--threads", "2"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const std::vector<CsvRow> rows = read_csv(dir.file("b-bandwidth.csv"));
    ASSERT_EQ(rows.size(), 4u);
    const CsvRow& ceiling = rows[2];
    const CsvRow& cpu = rows[3];
    EXPECT_EQ(ceiling.at("measure"), "cpu_in_cache");
    EXPECT_EQ(cpu.at("measure"), "cpu");
    const double bound = number(cpu, "bound_particle_steps_per_s");
    EXPECT_NEAR(number(cpu, "fraction_of_bound"), number(cpu, "particle_steps_per_s") / bound,
                1e-4 * number(cpu, "fraction_of_bound"));
    // The ceiling: one thread in the caches, times the two threads of the large run.
    EXPECT_EQ(number(ceiling, "threads"), 1);
    EXPECT_NEAR(number(cpu, "compute_ceiling_particle_steps_per_s"), 2 * number(ceiling, "particle_steps_per_s"),
                1e-4 * number(ceiling, "particle_steps_per_s"));
    // The bytes: the pair list's model (bench/bandwidth_suite.cpp) from the run's own list.
    const double p = number(cpu, "pairs_per_particle"), k = number(cpu, "steps_per_list_build");
    EXPECT_GT(p, 0.1);
    EXPECT_LT(p, 3.0);
    EXPECT_GE(k, 1.0);
    EXPECT_GT(number(cpu, "bytes_per_particle_step"), 76 + 8 * p);   // the per-step part alone
    EXPECT_LT(number(cpu, "bytes_per_particle_step"), 212);          // below the cell path's model
    EXPECT_TRUE(contains(result.out, "target: fraction_of_bound >= 0.6 at N = 1e6, 2 threads")) << result.out;
    EXPECT_TRUE(contains(result.out, "not the target's configuration")) << result.out;
}

// The throughput suite's two targets for cpu at N = 1e4 (processor ns per disk-step on one
// thread; disk-steps per second against Box2D 2.4 in the same run), each printed with its
// figures and a verdict that follows them.
TEST(BenchCommand, ThroughputSuitePrintsCpusTargetsWithTheirFigures) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"throughput", "--sizes", "10000", "--backend", "cpu", "--backend", "box2d",
                                         "--threads", "1", "--steps", "5"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const std::vector<CsvRow> rows = read_csv(dir.file("b-throughput.csv"));
    double cpu_ns = 0, cpu_rate = 0, box2d_rate = 0;
    for (const CsvRow& row : rows) {
        if (row.at("backend") == "cpu") cpu_ns = number(row, "cpu_ns_per_particle_step"), cpu_rate = number(row, "particle_steps_per_s");
        if (row.at("backend").rfind("box2d", 0) == 0) box2d_rate = std::max(box2d_rate, number(row, "particle_steps_per_s"));
    }
    ASSERT_GT(cpu_ns, 0) << result.out;
    ASSERT_GT(box2d_rate, 0) << result.out;
    char ns[32];
    std::snprintf(ns, sizeof ns, "measured %.2f ns", cpu_ns);
    EXPECT_TRUE(contains(result.out, "target: cpu <= 8 ns of a core per disk-step in cache (N = 1e4, 1 thread)")) << result.out;
    EXPECT_TRUE(contains(result.out, std::string(ns) + " \u2014 " + (cpu_ns <= 8 ? "met" : "not met"))) << result.out;
    const double ratio = cpu_rate / box2d_rate;
    char times[32];
    std::snprintf(times, sizeof times, ": %.0fx \u2014 %s", ratio, ratio >= 100 ? "met" : "not met");
    EXPECT_TRUE(contains(result.out, "target: cpu >= 100x Box2D 2.4's disk-steps/s at N = 1e4, same run")) << result.out;
    EXPECT_TRUE(contains(result.out, times)) << result.out;
}

// The opencl suite's launch-cost rows: both scenes of the library, both backends, the ratio
// of the two costs and the targets (3 for two disks, 1.5 for periodic_gas).
TEST(BenchCommand, OpenclSuitePrintsTheCostPerStepAgainstCpuWithItsTarget) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"opencl", "--quick", "--sizes", "500", "--backend", "opencl", "--backend", "cpu",
                                         "--steps", "3"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    std::map<std::string, CsvRow> launch_cost;
    for (const CsvRow& row : read_csv(dir.file("b-opencl.csv")))
        if (row.at("part") == "launch cost") launch_cost[row.at("scene")] = row;
    ASSERT_EQ(launch_cost.size(), 2u) << result.out;
    const std::map<std::string, std::pair<double, double>> expected = {{"head_on_equal", {2, 3.0}},
                                                                       {"periodic_gas", {1000, 1.5}}};
    for (const auto& [scene, disks_and_target] : expected) {
        SCOPED_TRACE(scene);
        const CsvRow& row = launch_cost.at(scene);
        EXPECT_EQ(number(row, "N"), disks_and_target.first);
        EXPECT_EQ(number(row, "target_ratio"), disks_and_target.second);
        // (A difference of two timings: on a loaded machine not even its sign is guaranteed.)
        EXPECT_TRUE(std::isfinite(number(row, "opencl_us_per_step")));
        EXPECT_TRUE(std::isfinite(number(row, "cpu_us_per_step")));
        EXPECT_NEAR(number(row, "ratio"), number(row, "opencl_us_per_step") / number(row, "cpu_us_per_step"),
                    1e-4 * number(row, "ratio"));
    }
}

TEST(BenchCommand, UnknownSuiteFailsNamingItAndTheKnownOnesBeforeRunningAny) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"event", "no_such_suite", "--quick"});
    EXPECT_NE(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, "no_such_suite")) << result.err;
    EXPECT_TRUE(contains(result.err, "event")) << "the message lists the suites: " << result.err;
    EXPECT_EQ(dir.entry_count(), 0u) << "the valid suite named first did not run";
}

TEST(BenchCommand, NonPositiveSizeIsRejected) {
    ScratchDirectory dir;
    const auto result = run_bench(dir, {"event", "--sizes", "0"});
    EXPECT_NE(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, "--sizes 0")) << result.err;
    EXPECT_EQ(dir.entry_count(), 0u);
}

}  // namespace
}  // namespace collide
