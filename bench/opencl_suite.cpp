// Benchmark suite `opencl`, two parts.
//
// Launch cost: the cost per step of `opencl` and `cpu` on two scenes of the library where the
// work per step is small, so that what is measured is the backend's own cost per step (kernel
// launches, queue round trips, thread wake-ups): head_on_equal (two disks) at the suite's
// finest dt, 2.5e-4, and periodic_gas (1000 disks). The cost per step is the time of a long
// run minus that of a 40-step run, over the steps between them (solver creation, loading and
// the first program build cancel out); each run is a whole `run_scene` with the scene's
// outputs, as a validation case runs it. Median of three; the ratio opencl/cpu is printed
// with its target.
//
// Throughput: particle-steps per second for N = 10^3 .. 10^6, with the grid built in one
// work-group (up to a few thousand disks), on the host (the OpenCL engine's design) and on the
// device, the last two with the disks moved into cell order at the default interval and never
// (sort_interval 0), and the time of each phase: host grid build, upload, read-back, device
// grid, reorder, kernels. The `cpu` backend, when compiled in, runs the same scenes for
// comparison.
//
// Throughput scene: the benchmark gas of bench_gas.h at area fraction 0.3, the same as the
// `throughput` suite's, so that the two suites' figures compare directly.
#include <algorithm>
#include <cmath>

#include "bench_suite.h"
#include "bench_gas.h"
#include "core/backend_registry.h"
#include "core/numerics/median.h"
#include "core/numerics/phase_timer.h"
#include "core/run_driver.h"
#include "core/scene/scene_loader.h"

#include "opencl/opencl_solver.h"

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
    report.add({{"part", std::string("throughput")},
                {"backend", backend.name},
                {"grid", grid},
                {"sort_interval", sort_interval_of(*solver)},
                {"N", n},
                {"steps", std::int64_t(steps)},
                {"particle_steps_per_s", double(n) * steps / seconds},
                {"ms_per_step", 1e3 * seconds / steps},
                {"host_grid_ms", per_step_ms(phase::grid_on_host)},
                {"upload_ms", per_step_ms(phase::upload)},
                {"readback_ms", per_step_ms(phase::read_back)},
                {"device_grid_ms", per_step_ms(phase::grid_on_device)},
                {"reorder_ms", per_step_ms(phase::reorder)},
                {"kernels_ms", per_step_ms(phase::device_steps)}});
    return seconds / steps;
}

// A scene of the library with a new dt and duration (the output interval shortened to the
// duration when it is longer).
Scene with_run(Scene scene, double dt, double duration) {
    scene.run.dt = dt;
    scene.run.duration = duration;
    scene.run.output_interval = std::min(scene.run.output_interval, duration);
    return scene;
}

// Seconds of one whole run: solver creation, load, every step and output.
double run_seconds(const BackendInfo& backend, const Scene& scene, const ParticleState<double>& initial) {
    return time_seconds([&] {
        auto solver = backend.create({});
        run_scene(scene, *solver, initial);
    });
}

struct LaunchCostCase {
    const char* scene;    // file in the scene library
    double dt;            // the suite's finest dt for the scene
    std::int64_t steps;   // of the long run; the short one has 40
    double target;        // opencl's cost per step at most this many times cpu's
};

// Microseconds per step of `backend` on `c`: (t(long run) - t(40 steps)) / the steps between,
// the median of three such differences.
double microseconds_per_step(const BackendInfo& backend, const LaunchCostCase& c, const Scene& scene,
                             const ParticleState<double>& initial) {
    constexpr std::int64_t short_steps = 40;
    const Scene short_run = with_run(scene, c.dt, double(short_steps) * c.dt);
    const Scene long_run = with_run(scene, c.dt, double(c.steps) * c.dt);
    run_seconds(backend, short_run, initial);  // the first build of the program is not timed
    std::vector<double> costs;
    for (int k = 0; k < 3; ++k) {
        const double t_short = run_seconds(backend, short_run, initial);
        const double t_long = run_seconds(backend, long_run, initial);
        costs.push_back(1e6 * (t_long - t_short) / double(c.steps - short_steps));
    }
    return median(costs);
}

void measure_launch_cost(const BackendInfo& opencl, const BackendInfo& cpu, const BenchArgs& args,
                         BenchReport& report) {
    const LaunchCostCase cases[] = {{"head_on_equal", 2.5e-4, 12000, 3.0}, {"periodic_gas", 1e-3, 2000, 1.5}};
    for (const LaunchCostCase& c : cases) {
        const Scene scene = load_scene(args.scene_dir + "/" + c.scene + ".toml");
        const ParticleState<double> initial = generate_initial_state(scene);
        const double cpu_us = microseconds_per_step(cpu, c, scene, initial);
        const double opencl_us = microseconds_per_step(opencl, c, scene, initial);
        report.add({{"part", std::string("launch cost")},
                    {"scene", std::string(c.scene)},
                    {"N", std::int64_t(initial.size())},
                    {"steps", c.steps},
                    {"opencl_us_per_step", opencl_us},
                    {"cpu_us_per_step", cpu_us},
                    {"ratio", opencl_us / cpu_us},
                    {"target_ratio", c.target}});
    }
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
    if (cpu && !args.scene_dir.empty() && wanted(args, "opencl") && wanted(args, "cpu"))
        measure_launch_cost(*opencl, *cpu, args, report);
    else report.note("launch cost not measured: it needs the opencl and cpu backends and the scene library");
    bool stopped = false;
    for (std::int64_t n : sizes) {
        for (const char* grid : {"group", "host", "device"})
            for (const bool reorder : {true, false}) {
                if (stopped || !wanted(args, "opencl")) break;
                if (grid == std::string("group") && (!reorder || std::size_t(n) > opencl::group_grid_up_to)) continue;  // never reorders; small N
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
    return {"opencl",
            "OpenCL backend: cost per step against cpu on two disks and periodic_gas (launch cost), "
            "particle-steps/s for N = 1e3..1e6, group vs host vs device grid, phase breakdown",
            run_suite};
}

}  // namespace collide::bench
