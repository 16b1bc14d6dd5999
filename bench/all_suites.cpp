// The benchmark suites compiled into collide. Adding a suite = one entry here.
#include "bench_suite.h"

namespace collide::bench {

BenchSuite event_bench_suite();  // event_bench.cpp
BenchSuite ecmc_bench_suite();   // ecmc_bench.cpp
void run_throughput_suite(const BenchArgs& args, BenchReport& report);  // throughput_suite.cpp
void run_features_suite(const BenchArgs& args, BenchReport& report);    // features_suite.cpp
void run_bandwidth_suite(const BenchArgs& args, BenchReport& report);   // bandwidth_suite.cpp
void run_view_suite(const BenchArgs& args, BenchReport& report);        // view_suite.cpp
void run_workflow_suite(const BenchArgs& args, BenchReport& report);    // workflow_suite.cpp

BenchSuite opencl_bench_suite();  // opencl_suite.cpp

const std::vector<BenchSuite>& all_bench_suites() {
    static const std::vector<BenchSuite> suites = {
        event_bench_suite(),
        ecmc_bench_suite(),
        opencl_bench_suite(),
        {"throughput", "particle-steps/s and time per phase, N = 1e3..1e6, every stepped backend", run_throughput_suite},
        {"features", "cpu: cost of each feature, saving of specialised loops, reorder by cell", run_features_suite},
        {"bandwidth", "STREAM triad bandwidth vs cpu bytes per particle-step", run_bandwidth_suite},
        {"view", "collide view headless: FPS and ms per frame (simulation, geometry, draw), cpu, N = 1e3..1e5", run_view_suite},
        {"workflow", "collide validate on the default suite (--jobs 2) and collide report on its results: wall time of each, median of --runs (3), against its target", run_workflow_suite},
    };
    return suites;
}

}  // namespace collide::bench
