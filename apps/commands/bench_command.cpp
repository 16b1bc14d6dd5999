// `collide bench [SUITE...] [--sizes ...] [--threads ...] [--steps N] [--out PREFIX]`
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <cstdio>
#include <memory>

#include "bench/bench_suite.h"
#include "commands.h"
#include "core/io/output_file.h"
#include "apps/resource_path.h"

namespace collide::cli {

void add_bench_command(CLI::App& app) {
    struct Args {
        std::vector<std::string> suites;
        std::string out = "bench";
        bench::BenchArgs bench;
    };
    auto args = std::make_shared<Args>();
    std::string suite_list;
    for (const auto& s : bench::all_bench_suites()) suite_list += "\n  " + s.name + ": " + s.description;
    auto* cmd = app.add_subcommand("bench", "Run benchmark suites headless; write CSV + JSON with provenance."
                                            "\nSuites:" + suite_list);
    cmd->add_option("suites", args->suites, "Suites to run (default: all)");
    cmd->add_option("--backend", args->bench.backends, "Only these backends");
    cmd->add_option("--sizes", args->bench.sizes, "Particle counts (default: each suite's ladder)");
    cmd->add_option("--threads", args->bench.threads, "Thread counts to try");
    // (Not --frames: `collide run --frames` is a switch that stores states; here it is a count.)
    cmd->add_option("--steps", args->bench.steps, "Timed steps of dt per scenario (stepping suites)")->capture_default_str();
    cmd->add_option("--runs", args->bench.runs, "Whole-command runs of the workflow suite (default 3)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--quick", args->bench.quick, "Small sizes only (smoke test)");
    cmd->add_option("--max-seconds", args->bench.max_seconds_per_case, "Stop a backend at the size where one case exceeds this")
        ->capture_default_str();
    cmd->add_option("-o,--out", args->out, "Output prefix: PREFIX-SUITE.csv and .json")->capture_default_str();
    cmd->callback([args] {
        // Every name and size is checked before anything runs: a typo in the last of several
        // suites must not be found after the first ones have run for minutes.
        std::string known;
        for (const auto& suite : bench::all_bench_suites()) known += (known.empty() ? "" : ", ") + suite.name;
        for (const auto& name : args->suites) {
            const auto& all = bench::all_bench_suites();
            if (std::none_of(all.begin(), all.end(), [&](const auto& s) { return s.name == name; }))
                throw std::runtime_error("unknown benchmark suite '" + name + "' (known: " + known + ")");
        }
        for (std::int64_t n : args->bench.sizes)
            if (n <= 0) throw std::runtime_error("--sizes " + std::to_string(n) + ": a particle count must be positive");
        auto chosen = [&](const bench::BenchSuite& suite) {
            return args->suites.empty() ||
                   std::find(args->suites.begin(), args->suites.end(), suite.name) != args->suites.end();
        };
        // So are the output files (core/io/output_file.h): a FIFO or a device in the way of the
        // last suite's results is refused before the first suite runs.
        for (const auto& suite : bench::all_bench_suites())
            if (chosen(suite))
                for (const char* ext : {".csv", ".json"}) check_output_path(args->out + "-" + suite.name + ext);
        args->bench.scene_dir = resource_path("data/scenes");
        args->bench.suite_dir = resource_path("validation/suites");
        bool ran = false;
        for (const auto& suite : bench::all_bench_suites()) {
            if (!chosen(suite)) continue;
            bench::BenchReport report(suite.name);
            suite.run(args->bench, report);
            report.write(args->out + "-" + suite.name);
            std::printf("wrote %s-%s.csv and .json\n", args->out.c_str(), suite.name.c_str());
            ran = true;
        }
        if (!ran) throw std::runtime_error("no benchmark suite matched; see `collide bench --help`");
    });
}

}  // namespace collide::cli
