// The benchmark suites compiled into collide. Adding a suite = one entry here.
#include "bench_suite.h"

namespace collide::bench {

BenchSuite opencl_bench_suite();  // opencl_suite.cpp

const std::vector<BenchSuite>& all_bench_suites() {
    static const std::vector<BenchSuite> suites = {
        opencl_bench_suite(),
    };
    return suites;
}

}  // namespace collide::bench
