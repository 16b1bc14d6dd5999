// The benchmark suites compiled into collide. Adding a suite = one entry here.
#include "bench_suite.h"

namespace collide::bench {

BenchSuite event_bench_suite();  // event_bench.cpp

const std::vector<BenchSuite>& all_bench_suites() {
    static const std::vector<BenchSuite> suites = {
        event_bench_suite(),
    };
    return suites;
}

}  // namespace collide::bench
