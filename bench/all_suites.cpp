// The benchmark suites compiled into collide. Adding a suite = one entry here.
#include "bench_suite.h"

namespace collide::bench {

const std::vector<BenchSuite>& all_bench_suites() {
    static const std::vector<BenchSuite> suites = {
    };
    return suites;
}

}  // namespace collide::bench
