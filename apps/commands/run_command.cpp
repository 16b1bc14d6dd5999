// `collide run SCENE --backend NAME [--out FILE] [--frames]`: one scene on one backend.
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "apps/progress_line.h"
#include "commands.h"
#include "core/backend_registry.h"
#include "core/provenance.h"
#include "core/run_driver.h"
#include "core/scene_loader.h"

namespace collide::cli {
namespace {

struct RunArgs {
    std::string scene_path;
    std::string backend = "step";
    std::string out;
    bool frames = false;
    BackendOptions options;
};

double relative_change(double initial, double final_value) {
    const double scale = std::fabs(initial);
    return scale > 0 ? (final_value - initial) / scale : final_value - initial;
}

void print_summary(const Scene& scene, const std::string& backend, const RunResult& r) {
    const Metrics& a = r.series.front();
    const Metrics& b = r.series.back();
    std::printf("scene     %s (%zu disks, seed %llu)\n", scene.name.c_str(), r.final_state.size(),
                static_cast<unsigned long long>(scene.seed));
    std::printf("backend   %s, %lld steps, %lld contacts, %.3f s wall time\n", backend.c_str(),
                static_cast<long long>(r.stats.steps), static_cast<long long>(r.stats.contacts),
                r.wall_seconds);
    std::printf("energy    kinetic %.15g -> %.15g (relative change %.3e)\n", a.kinetic_energy,
                b.kinetic_energy, relative_change(a.kinetic_energy, b.kinetic_energy));
    if (scene.has_gravity())
        std::printf("          total   %.15g -> %.15g (relative change %.3e)\n", a.total_energy(),
                    b.total_energy(), relative_change(a.total_energy(), b.total_energy()));
    const double p0 = std::hypot(a.momentum_x, a.momentum_y);
    const double dp = std::hypot(b.momentum_x - a.momentum_x, b.momentum_y - a.momentum_y);
    std::printf("momentum  (%.15g, %.15g) -> (%.15g, %.15g), |change| %.3e%s\n", a.momentum_x,
                a.momentum_y, b.momentum_x, b.momentum_y, p0 > 0 ? dp / p0 : dp,
                p0 > 0 ? " relative" : " absolute");
    std::printf("overlap   final: %lld pairs, max depth %.3e, mean depth %.3e (relative to r_i+r_j)\n",
                static_cast<long long>(b.overlapping_pairs), b.max_overlap, b.mean_overlap);
    std::printf("walls     final max penetration %.3e (relative to radius)\n", b.max_wall_penetration);
}

// Every check that can fail fast comes before the simulation: the backend name (no file read
// needed), the scene, whether the backend supports it, and whether the output can be written.
// A failure at any point leaves no output file and an existing one untouched (RunWriter).
void execute(const RunArgs& args) {
    const BackendInfo& backend = find_backend(args.backend);
    const Scene scene = load_scene(args.scene_path);
    require_support(backend, scene);
    const ParticleState<double> initial = generate_initial_state(scene);
    auto solver = backend.create(args.options);

    std::unique_ptr<RunWriter> writer;
    if (!args.out.empty()) writer = std::make_unique<RunWriter>(args.out, args.frames);
    ProgressLine progress;
    RunOptions run_options;
    run_options.writer = writer.get();
    run_options.on_output = [&progress](double time, double duration) { progress.update(time, duration); };
    const RunResult result = run_scene(scene, *solver, initial, run_options);
    progress.finish();

    if (writer) {
        writer->write_attributes(run_provenance(scene, backend.name, *solver));
        writer->commit();
    }
    print_summary(scene, backend.name, result);
    if (writer) std::printf("output    %s\n", args.out.c_str());
}

}  // namespace

void require_support(const BackendInfo& backend, const Scene& scene) {
    if (auto reason = backend.supports(scene))
        throw std::runtime_error("backend '" + backend.name + "' cannot run scene '" + scene.name + "': " + *reason);
}

void add_run_command(CLI::App& app) {
    auto args = std::make_shared<RunArgs>();
    auto* cmd = app.add_subcommand("run", "Run one scene on one backend; write metrics (and frames) to HDF5");
    cmd->add_option("scene", args->scene_path, "Scene file (TOML)")->required()->check(CLI::ExistingFile);
    cmd->add_option("-b,--backend", args->backend, "Backend name (see `collide backends`)")->capture_default_str();
    cmd->add_option("-o,--out", args->out, "HDF5 output file (written atomically)");
    cmd->add_flag("--frames", args->frames, "Also store positions and velocities at every output time");
    cmd->add_option("--threads", args->options.threads, "Threads for multi-threaded backends (0 = all)");
    cmd->add_option("--real", args->options.real, "Precision for backends that offer both")
        ->check(CLI::IsMember({"float", "double"}));
    cmd->add_option("--cl-device", args->options.device, "OpenCL device (index or name substring)");
    cmd->callback([args] { execute(*args); });
}

}  // namespace collide::cli
