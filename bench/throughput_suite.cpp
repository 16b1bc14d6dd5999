// Suite `throughput`: ParticleBox's headless benchmark made real. Every registered stepped
// backend that supports the scene runs the benchmark gas (area fraction 0.3, collide-first)
// for 240 steps of dt (--steps; ParticleBox's 240 frames) at N = 10^3 ... 10^6; `cpu` at 1 and
// 2 threads. A backend stops at the first N where one step takes longer than max_seconds /
// steps. The event
// solver has its own suite (its cost is per collision, not per step).
#include <algorithm>
#include <cstdio>

#include "frame_timing.h"

namespace collide::bench {

std::vector<int> thread_counts(const BenchArgs& args, const std::string& backend) {
    if (!args.threads.empty()) return args.threads;
    if (backend == "cpu") return {1, 2};
    return {0};  // the backend's default
}

void run_throughput_suite(const BenchArgs& args, BenchReport& report) {
    std::vector<std::int64_t> sizes = args.sizes;
    if (sizes.empty()) sizes = args.quick ? std::vector<std::int64_t>{1000, 10000}
                                          : std::vector<std::int64_t>{1000, 10000, 100000, 1000000};
    const double frame_limit = args.max_seconds_per_case / args.steps;
    for (const auto& backend : all_backends()) {
        if (backend.name == "event" || !wanted(args, backend.name)) continue;
        for (int threads : thread_counts(args, backend.name)) {
            for (std::int64_t n : sizes) {
                const GasCase gas = bench_gas(n);
                if (auto reason = backend.supports(gas.scene)) {
                    report.note(backend.name + " left out: " + *reason);
                    break;
                }
                BackendOptions options;
                options.threads = threads;
                const FrameTiming t = measure_frames(backend, options, gas, args.steps, frame_limit);
                if (t.stopped) {
                    char text[200];
                    std::snprintf(text, sizeof text, "%s (threads %s) stopped at N = %lld: one frame took %.3g s > %.3g s",
                                  backend.name.c_str(), t.threads.c_str(), static_cast<long long>(n),
                                  t.first_frame_seconds, frame_limit);
                    report.note(text);
                    break;
                }
                Row row{{"backend", backend.name}, {"rule", "collide-first"}, {"area_fraction", 0.3},
                        {"steps", std::int64_t(args.steps)}};
                add_timing(row, t, n);
                report.add(row);
            }
        }
    }
}

}  // namespace collide::bench
