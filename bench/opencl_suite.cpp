// Benchmark suite `opencl`: throughput of the OpenCL backend in particle-steps per second for
// N = 10^3 .. 10^6, with the grid built on the host (the OpenCL engine's design) and on the device,
// each with the disks moved into cell order at the default interval and never
// (sort_interval 0), and the time of each phase: host grid build, upload, read-back, device
// grid, reorder, kernels. The `cpu` backend, when compiled in, runs the same scenes for
// comparison.
//
// Scene: the benchmark gas of bench_gas.h at area fraction 0.3, the same as the `throughput`
// suite's, so that the two suites' figures compare directly.
#include <algorithm>
#include <cmath>

#include "bench_suite.h"
#include "bench_gas.h"
#include "core/backend_registry.h"

namespace collide::bench {
namespace {

double phase(const SolverStats& s, const char* name) {
    const auto it = s.phase_seconds.find(name);
    return it == s.phase_seconds.end() ? 0.0 : it->second;
}

// The reorder interval the solver runs with, from the provenance of the two backends this
// suite runs ("-" if it names none).
std::string sort_interval_of(const Solver& solver) {
    const auto provenance = solver.provenance();
    for (const char* key : {"sort_interval", "cpu.sort_interval"})
        if (const auto it = provenance.find(key); it != provenance.end()) return it->second;
    return "-";
}

// Runs one case and adds its row; returns the seconds per step.
double measure(const BackendInfo& backend, const BackendOptions& options, const std::string& grid, std::int64_t n,
               const BenchArgs& args, BenchReport& report) {
    const GasCase gas = bench_gas(n);
    const Scene& scene = gas.scene;
    const ParticleState<double>& initial = gas.initial;
    auto solver = backend.create(options);
    solver->load(scene, initial);
    // Warm-up: the first steps pay for lazy allocation and first-touch of the buffers.
    const int warmup = 2;
    solver->advance_to(warmup * scene.run.dt);
    const SolverStats before = solver->stats();
    // Enough steps for about 2e7 particle-steps, within [3, steps] (fewer with --quick).
    const int cap = args.quick ? std::min(args.steps, 10) : args.steps;
    const int steps = int(std::clamp<std::int64_t>(20'000'000 / n, 3, std::max(cap, 3)));
    const double seconds = time_seconds([&] { solver->advance_to((warmup + steps) * scene.run.dt); });
    const SolverStats after = solver->stats();
    auto per_step_ms = [&](const char* name) { return 1e3 * (phase(after, name) - phase(before, name)) / steps; };
    report.add({{"backend", backend.name},
                {"grid", grid},
                {"sort_interval", sort_interval_of(*solver)},
                {"N", n},
                {"steps", std::int64_t(steps)},
                {"particle_steps_per_s", double(n) * steps / seconds},
                {"ms_per_step", 1e3 * seconds / steps},
                {"host_grid_ms", per_step_ms("grid (host)")},
                {"upload_ms", per_step_ms("upload")},
                {"readback_ms", per_step_ms("read-back")},
                {"device_grid_ms", per_step_ms("grid (device)")},
                {"reorder_ms", per_step_ms("reorder")},
                {"kernels_ms", per_step_ms("kernels")}});
    return seconds / steps;
}

void run_suite(const BenchArgs& args, BenchReport& report) {
    std::vector<std::int64_t> sizes = args.sizes;
    if (sizes.empty()) sizes = args.quick ? std::vector<std::int64_t>{1000, 10000}
                                          : std::vector<std::int64_t>{1000, 10000, 100000, 1000000};
    const BackendInfo* opencl = backend_if_built("opencl");
    const BackendInfo* cpu = backend_if_built("cpu");
    if (!opencl) {
        report.note("the opencl backend is not compiled into this build");
        return;
    }
    bool stopped = false;
    for (std::int64_t n : sizes) {
        for (const char* grid : {"host", "device"})
            for (const bool reorder : {true, false}) {
                if (stopped || !wanted(args, "opencl")) break;
                BackendOptions options;
                options.extra["grid"] = grid;
                if (!reorder) options.extra.emplace("sort_interval", "0");  // else the backend's default
                if (measure(*opencl, options, grid, n, args, report) > args.max_seconds_per_case) {
                    report.note("opencl stopped after N = " + std::to_string(n) + ": one step exceeded --max-seconds");
                    stopped = true;
                }
            }
        if (cpu && wanted(args, "cpu"))
            for (int threads : args.threads.empty() ? std::vector<int>{0} : args.threads) {
                BackendOptions options;
                options.threads = threads;
                measure(*cpu, options, "-", n, args, report);
            }
    }
    if (!cpu) report.note("the cpu backend is not compiled into this build: no comparison rows");
}

}  // namespace

BenchSuite opencl_bench_suite() {
    return {"opencl", "OpenCL backend: particle-steps/s for N = 1e3..1e6, host vs device grid, phase breakdown",
            run_suite};
}

}  // namespace collide::bench
