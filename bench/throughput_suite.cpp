// Suite `throughput`: ParticleBox's headless benchmark made real. Every registered stepped
// backend that supports the scene runs the benchmark gas (area fraction 0.3, collide-first)
// for 240 steps of dt (--steps; ParticleBox's 240 frames) at N = 10^3 ... 10^6; `cpu` at 1 and
// 2 threads; `box2d` once per preset (tuned and shipped, docs/box2d-baseline.md) so the speed
// cost of tuning shows. A backend stops at the first N where one step takes longer than
// max_seconds / steps. A backend with no time step is left out by what it claims, not by its
// name: the exact solvers have their own suite (`event`: their cost is per collision, not per
// step), and the samplers have no time at all (a "step" of theirs would measure nothing
// comparable; suite `ecmc` times `ecmc` per lift).
#include <algorithm>
#include <cstdio>

#include "frame_timing.h"

namespace collide::bench {
namespace {

std::vector<int> thread_counts(const BenchArgs& args, const std::string& backend) {
    if (!args.threads.empty()) return args.threads;
    if (backend == "cpu") return {1, 2};
    return {0};  // the backend's default
}

// One way to run a backend: the name the rows carry and the [backend.NAME] keys it sets.
struct Configuration {
    std::string label;
    std::map<std::string, std::string> options;
};

std::vector<Configuration> configurations(const std::string& backend) {
    if (backend == "box2d") return {{"box2d", {{"preset", "tuned"}}}, {"box2d[shipped]", {{"preset", "shipped"}}}};
    return {{backend, {}}};
}

// Why a backend has no place in a suite of time steps, or nullptr when it has one.
const char* no_time_step(const BackendInfo& backend) {
    if (backend.exact) return "exact (event-driven), it has no time step; `collide bench event` times it per collision";
    if (backend.sampler) return "a sampler has no time and no time step; its cost is per lift or trial move, not per step (`collide bench ecmc` times ecmc)";
    return nullptr;
}

// One backend, configuration and thread count over the sizes, up to the first too-slow step.
void run_sizes(const BenchArgs& args, BenchReport& report, const BackendInfo& backend, const Configuration& config,
               int threads, const std::vector<std::int64_t>& sizes) {
    const double frame_limit = args.max_seconds_per_case / args.steps;
    for (std::int64_t n : sizes) {
        GasCase gas = bench_gas(n);
        if (!config.options.empty()) gas.scene.backend_options[backend.name] = config.options;
        if (auto reason = backend.supports(gas.scene)) {
            report.note(config.label + " left out: " + *reason);
            return;
        }
        BackendOptions options;
        options.threads = threads;
        const FrameTiming t = measure_frames(backend, options, gas, args.steps, frame_limit);
        if (t.stopped) {
            char text[200];
            std::snprintf(text, sizeof text, "%s (threads %s) stopped at N = %lld: one step took %.3g s > %.3g s",
                          config.label.c_str(), t.threads.c_str(), static_cast<long long>(n), t.first_frame_seconds,
                          frame_limit);
            report.note(text);
            return;
        }
        Row row{{"backend", config.label}, {"rule", "collide-first"}, {"area_fraction", 0.3},
                {"steps", std::int64_t(args.steps)}};
        add_timing(row, t, n);
        report.add(row);
        report.work_done(double(n) * args.steps, config.label + " N = " + std::to_string(n) + " done");
    }
}

// Issue 51's targets for `cpu`, as verdicts, when the suite ran their rows (N = 1e4): at most
// 8 ns of a core per disk-step on one thread (in cache), and at least 100 times the disk-steps
// per second of Box2D 2.4 (its faster preset) in the same run (cpu at its best thread count).
void note_targets(BenchReport& report) {
    constexpr std::int64_t n_target = 10000;
    const Row* one_thread = nullptr;
    double cpu_best = 0, box2d_best = 0;
    for (const Row& row : report.rows()) {
        const auto n = row.find("n");
        if (n == row.end() || std::get<std::int64_t>(n->second) != n_target) continue;
        const std::string& name = std::get<std::string>(row.at("backend"));
        const double rate = std::get<double>(row.at("particle_steps_per_s"));
        if (name == "cpu") {
            cpu_best = std::max(cpu_best, rate);
            if (std::get<std::string>(row.at("threads")) == "1") one_thread = &row;
        } else if (name.rfind("box2d", 0) == 0) {
            box2d_best = std::max(box2d_best, rate);
        }
    }
    char text[300];
    if (one_thread) {
        const double ns = std::get<double>(one_thread->at("cpu_ns_per_particle_step"));
        std::snprintf(text, sizeof text,
                      "target: cpu <= 8 ns of a core per disk-step in cache (N = 1e4, 1 thread) \u2014 measured %.2f ns \u2014 %s",
                      ns, ns <= 8.0 ? "met" : "not met");
        report.note(text);
    }
    if (cpu_best > 0 && box2d_best > 0) {
        const double ratio = cpu_best / box2d_best;
        std::snprintf(text, sizeof text,
                      "target: cpu >= 100x Box2D 2.4's disk-steps/s at N = 1e4, same run \u2014 cpu %.3g (best thread "
                      "count), box2d %.3g (faster preset): %.0fx \u2014 %s",
                      cpu_best, box2d_best, ratio, ratio >= 100 ? "met" : "not met");
        report.note(text);
    }
}

}  // namespace

void run_throughput_suite(const BenchArgs& args, BenchReport& report) {
    std::vector<std::int64_t> sizes = args.sizes;
    if (sizes.empty()) sizes = args.quick ? std::vector<std::int64_t>{1000, 10000}
                                          : std::vector<std::int64_t>{1000, 10000, 100000, 1000000};
    // Plan first (for the progress line's time left), then run.
    struct Planned {
        const BackendInfo* backend;
        Configuration config;
        int threads;
    };
    std::vector<Planned> plan;
    for (const auto& backend : all_backends()) {
        if (const char* why = no_time_step(backend)) {
            if (!args.backends.empty() && wanted(args, backend.name)) report.note(backend.name + " left out: " + why);
            continue;
        }
        for (const Configuration& config : configurations(backend.name)) {
            // --backend box2d runs both presets; --backend "box2d[shipped]" only that one.
            if (!wanted(args, backend.name) && !wanted(args, config.label)) continue;
            for (int threads : thread_counts(args, backend.name)) plan.push_back({&backend, config, threads});
        }
    }
    double disk_steps = 0;
    for (std::int64_t n : sizes) disk_steps += double(n) * args.steps;
    report.expect_work(disk_steps * double(plan.size()));
    for (const Planned& p : plan) run_sizes(args, report, *p.backend, p.config, p.threads, sizes);
    note_targets(report);
}

}  // namespace collide::bench
