// Suite `view`: how fast `collide view` draws, headless, on the `cpu` backend (integrate-first
// rule with 4 sub-steps, 2 threads; ParticleBox's setting) for N = 10^3, 10^4, 10^5 disks of the
// benchmark gas. One frame = one time step dt, drawn off-screen at 1280x720 as `collide view
// --headless` draws it: SDL's software renderer's surface, filled by the canvas's CPU rasteriser
// (its path for software renderers), HUD and overlap marks included. The target is 60 frames
// per second at N = 10^5 (docs/viewer.md records the figures).
#include <chrono>
#include <cstdio>

#include "bench_suite.h"
#include "core/backend_registry.h"
#include "bench_gas.h"
#include "view/live_viewer.h"

namespace collide::bench {
namespace {

constexpr int warm_up_frames = 10;

struct ViewTiming {
    double seconds = 0;
    view::FrameTimes sum;
};

ViewTiming time_frames(view::ViewSession& session, int frames) {
    view::Canvas canvas(1280, 720);
    view::Geometry geometry;
    for (int k = 0; k < warm_up_frames; ++k) view::draw_frame(session, canvas, geometry, 1, "");
    ViewTiming t;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < frames; ++k) {
        const view::FrameTimes f = view::draw_frame(session, canvas, geometry, 1, "");
        t.sum.simulation += f.simulation;
        t.sum.geometry += f.geometry;
        t.sum.draw += f.draw;
    }
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

}  // namespace

void run_view_suite(const BenchArgs& args, BenchReport& report) {
    if (!wanted(args, "cpu")) return;
    std::vector<std::int64_t> sizes = args.sizes;
    if (sizes.empty()) sizes = args.quick ? std::vector<std::int64_t>{1000} : std::vector<std::int64_t>{1000, 10000, 100000};
    const std::vector<int> threads = args.threads.empty() ? std::vector<int>{2} : args.threads;
    const BackendInfo& cpu = find_backend("cpu");
    for (int thread_count : threads) {
        for (std::int64_t n : sizes) {
            GasCase gas = bench_gas(n);
            gas.scene.run.order = StepOrder::integrate_first;
            gas.scene.run.substeps = 4;
            gas.scene.run.output_interval = gas.scene.run.dt;  // one output step = one dt per frame
            BackendOptions options;
            options.threads = thread_count;
            view::ViewSession session(gas.scene, gas.initial, cpu, nullptr, options);
            const ViewTiming t = time_frames(session, args.steps);
            const double per_frame = 1e3 / args.steps;
            report.add(Row{{"backend", "cpu"}, {"n", n}, {"threads", std::int64_t(thread_count)}, {"substeps", std::int64_t(4)},
                           {"frames", std::int64_t(args.steps)}, {"fps", args.steps / t.seconds},
                           {"ms_per_frame", per_frame * t.seconds}, {"ms_simulation", per_frame * t.sum.simulation},
                           {"ms_geometry", per_frame * t.sum.geometry}, {"ms_draw", per_frame * t.sum.draw}});
        }
    }
}

}  // namespace collide::bench
