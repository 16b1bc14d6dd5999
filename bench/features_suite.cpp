// Suite `features`: what each optional feature costs the `cpu` backend, what the loops
// specialised to a scene's features save against the generic loop (every feature compiled in,
// switched off by zero values at run time), and what reordering particles by cell buys.
// One gas (area fraction 0.3, N = 10^5; --quick 10^4), all threads unless --threads.
#include <functional>

#include "cpu/cpu_solver.h"
#include "frame_timing.h"

namespace collide::bench {

namespace {

struct Variant {
    std::string name;
    std::function<void(GasCase&)> apply;
};

std::vector<Variant> variants() {
    return {
        {"none", [](GasCase&) {}},
        {"gravity", [](GasCase& g) { g.scene.physics.gravity_y = -0.5; }},
        {"damping", [](GasCase& g) { g.scene.physics.damping = 0.1; }},
        {"friction", [](GasCase& g) { g.scene.physics.friction = 0.1; g.scene.physics.restitution = 0.9; }},
        {"stones", [](GasCase& g) {
             for (std::size_t i = 0; i < g.initial.size(); i += 100) {
                 g.initial.inv_mass[i] = 0;
                 g.initial.vx[i] = g.initial.vy[i] = 0;
             }
         }},
        {"polydisperse", [](GasCase& g) {
             // radii 0.35 ... 0.5 (still apart: the placement assumed 0.5)
             for (std::size_t i = 0; i < g.initial.size(); ++i) g.initial.radius[i] = 0.35 + 0.15 * double(i % 16) / 15;
         }},
        {"periodic", [](GasCase& g) { g.scene.world.boundary = Boundary::periodic; }},
        {"particle_box", [](GasCase& g) {  // ParticleBox's material and rule, all features at once
             g.scene.physics = Physics{0.4, 0.85, 0.1, 0.0, -0.5, 0.01};
             g.scene.run.order = StepOrder::integrate_first;
             g.scene.run.substeps = 4;
             for (std::size_t i = 0; i < g.initial.size(); i += 100) {
                 g.initial.inv_mass[i] = 0;
                 g.initial.vx[i] = g.initial.vy[i] = 0;
             }
         }},
    };
}

}  // namespace

void run_features_suite(const BenchArgs& args, BenchReport& report) {
    const std::int64_t n = !args.sizes.empty() ? args.sizes.front() : args.quick ? 10000 : 100000;
    const int threads = args.threads.empty() ? 0 : args.threads.front();
    const BackendInfo& cpu = find_backend("cpu");
    const double no_limit = 1e9;
    const double default_skin = cpu::CpuSolver::kDefaultSkin;
    auto run = [&](const std::string& variant, const GasCase& gas, const std::string& specialise, int sort_interval,
                   double skin = cpu::CpuSolver::kDefaultSkin) {
        BackendOptions options;
        options.threads = threads;
        options.extra = {{"specialise", specialise}, {"sort_interval", std::to_string(sort_interval)},
                         {"skin", std::to_string(skin)}};
        const FrameTiming t = measure_frames(cpu, options, gas, args.steps, no_limit);
        Row row{{"backend", "cpu"}, {"feature", variant}, {"specialise", specialise},
                {"sort_interval", std::int64_t(sort_interval)}, {"skin", skin}, {"steps", std::int64_t(args.steps)},
                {"rule", to_string(gas.scene.run.order)}};
        add_timing(row, t, n);
        report.add(row);
    };
    const int default_sort = cpu::CpuSolver::kDefaultSortInterval;
    for (const auto& v : variants()) {
        GasCase gas = bench_gas(n);
        v.apply(gas);
        run(v.name, gas, "on", default_sort);
        run(v.name, gas, "off", default_sort);
    }
    const GasCase plain = bench_gas(n);
    for (int k : {0, 4, 16}) run("none", plain, "on", k);
    for (double skin : {0.0, 0.1, 0.25, 0.5, 0.75, 1.0})
        if (skin != default_skin) run("none", plain, "on", default_sort, skin);
    report.note("sort_interval K = particles moved into cell order at every K-th grid build, 0 = never; the default is " + std::to_string(default_sort));
    report.note("skin s = the pair list's reach r_i + r_j + s * 2 r_max (0: no list, the grid and every disk's 3x3 neighbourhood at every step); the default is " + std::to_string(default_skin));
}

}  // namespace collide::bench
