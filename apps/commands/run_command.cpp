// `collide run SCENE --backend NAME [--out FILE] [--frames]`: one scene on one backend.
#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "core/io/input_file.h"
#include "core/text/printable.h"
#include "core/io/progress_line.h"
#include "commands.h"
#include "core/backend_registry.h"
#include "core/io/provenance.h"
#include "core/run_driver.h"
#include "core/scene/scene_loader.h"

namespace collide::cli {
namespace {

// The temporary output file, removed by the handler of SIGINT, SIGTERM and SIGHUP (Ctrl-C, a
// kill, a closed terminal) before the signal ends the program as it would have: RunWriter's
// destructor never runs then. A fixed buffer, because a handler may only call
// async-signal-safe functions (unlink, signal, raise), not touch a std::string.
char temporary_to_remove[4096] = "";

extern "C" void remove_temporary_and_die(int signal_number) {
    if (temporary_to_remove[0]) ::unlink(temporary_to_remove);
    ::signal(signal_number, SIG_DFL);
    ::raise(signal_number);
}

// Holds SIGINT, SIGTERM and SIGHUP back while it lives; a signal that arrives meanwhile is
// delivered when it ends.
class StopSignalsBlocked {
public:
    StopSignalsBlocked() {
        sigset_t stop;
        sigemptyset(&stop);
        for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stop, s);
        ::sigprocmask(SIG_BLOCK, &stop, &previous_);
    }
    ~StopSignalsBlocked() { ::sigprocmask(SIG_SETMASK, &previous_, nullptr); }
    StopSignalsBlocked(const StopSignalsBlocked&) = delete;
    StopSignalsBlocked& operator=(const StopSignalsBlocked&) = delete;

private:
    sigset_t previous_;
};

// Arms the handlers for the writer's temporary file while it exists; disarms them after.
class TemporaryFileGuard {
public:
    explicit TemporaryFileGuard(const RunWriter* writer) {
        if (!writer || writer->temporary_path().size() >= sizeof temporary_to_remove) return;
        std::snprintf(temporary_to_remove, sizeof temporary_to_remove, "%s", writer->temporary_path().c_str());
        for (int s : {SIGINT, SIGTERM, SIGHUP}) ::signal(s, remove_temporary_and_die);
    }
    ~TemporaryFileGuard() {
        for (int s : {SIGINT, SIGTERM, SIGHUP}) ::signal(s, SIG_DFL);
        temporary_to_remove[0] = '\0';
    }
    TemporaryFileGuard(const TemporaryFileGuard&) = delete;
    TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;
};

struct RunArgs {
    std::string scene_path;
    std::string backend = "step";
    std::string out;
    bool frames = false;
    BackendOptions options;
    std::vector<SceneOverride> overrides;
};

double relative_change(double initial, double final_value) {
    const double scale = std::fabs(initial);
    return scale > 0 ? (final_value - initial) / scale : final_value - initial;
}

// beta P d^2 with its batch-means error, where the backend recorded it (the pressure record of
// docs/validation.md, "Error bars and mixing": event, event-plain, ecmc, metropolis).
void print_pressure(const SolverStats& stats) {
    const auto& c = stats.counters;
    const auto value = c.find("beta_pressure"), error = c.find("beta_pressure_error");
    if (value == c.end() || error == c.end()) return;
    auto counter = [&c](const char* name) { const auto it = c.find(name); return it == c.end() ? 0.0 : it->second; };
    std::printf("pressure  beta P d^2 = %.9g +- %.3g (batch means: %g batches, tau_int %.4g, equilibration cut %.4g",
                value->second, error->second, counter("beta_pressure_batches"),
                counter("beta_pressure_correlation_time"), counter("beta_pressure_equilibration"));
    if (c.count("psi6_traversals"))
        std::printf("; psi6 traversals %g%s", counter("psi6_traversals"), counter("psi6_mixed") != 0 ? "" : ", NOT MIXED");
    std::printf(")\n");
}

void print_summary(const Scene& scene, const std::string& backend, const RunResult& r) {
    const Metrics& a = r.series.front();
    const Metrics& b = r.series.back();
    std::printf("scene     %s (%zu disks, seed %llu)\n", printable(scene.name).c_str(), r.final_state.size(),
                static_cast<unsigned long long>(scene.seed));
    if (!scene.overrides.empty()) std::printf("set       %s\n", scene.overrides.c_str());
    std::printf("backend   %s, %lld steps, %lld contacts, %.3f s wall time\n", backend.c_str(),
                static_cast<long long>(r.stats.steps), static_cast<long long>(r.stats.contacts),
                r.wall_seconds);
    print_pressure(r.stats);
    if (const BackendInfo* info = backend_if_built(backend); info && info->sampler) {
        // No velocities: the energy and momentum lines would read zeros.
        std::printf("dynamics  none (%s)\n", info->sampler_left_out().c_str());
        std::printf("overlap   final: %lld pairs, max depth %.3e, mean depth %.3e (relative to r_i+r_j)\n",
                    static_cast<long long>(b.overlapping_pairs), b.max_overlap, b.mean_overlap);
        return;
    }
    std::printf("energy    kinetic %.15g -> %.15g (relative change %.3e)\n", a.kinetic_energy,
                b.kinetic_energy, relative_change(a.kinetic_energy, b.kinetic_energy));
    if (scene.has_gravity())
        std::printf("          total   %.15g -> %.15g (relative change %.3e)\n", a.total_energy(),
                    b.total_energy(), relative_change(a.total_energy(), b.total_energy()));
    // The change relative to sqrt(2 M K), the momentum the moving mass would have at the rms
    // speed: a periodic Maxwell draw starts at P = 0 to rounding, which is no scale.
    double mass = 0;
    for (std::size_t i = 0; i < r.final_state.size(); ++i)
        if (!r.final_state.is_stone(i)) mass += r.final_state.mass[i];
    const double scale = std::sqrt(2 * mass * a.kinetic_energy);
    const double dp = std::hypot(b.momentum_x - a.momentum_x, b.momentum_y - a.momentum_y);
    std::printf("momentum  (%.15g, %.15g) -> (%.15g, %.15g), |change| %.3e%s\n", a.momentum_x,
                a.momentum_y, b.momentum_x, b.momentum_y, scale > 0 ? dp / scale : dp,
                scale > 0 ? " of sqrt(2 M K)" : " absolute");
    std::printf("overlap   final: %lld pairs, max depth %.3e, mean depth %.3e (relative to r_i+r_j)\n",
                static_cast<long long>(b.overlapping_pairs), b.max_overlap, b.mean_overlap);
    std::printf("walls     final max penetration %.3e (relative to radius)\n", b.max_wall_penetration);
}

// Every check that can fail fast comes before the simulation: the backend name (no file read
// needed), the scene, whether the backend supports it, and whether the output can be written.
// A failure at any point leaves no output file and an existing one untouched (RunWriter).
void execute(const RunArgs& args) {
    remember_input(args.scene_path);  // `--out` naming the scene file is refused (core/io/input_file.h)
    const BackendInfo& backend = find_backend(args.backend);
    const Scene scene = load_scene_with_overrides(args.scene_path, args.overrides);
    require_support(backend, scene);
    const ParticleState<double> initial = generate_initial_state(scene);
    auto solver = backend.create(args.options);

    // The guard outlives the writer, so the handlers stay armed until the temporary file is gone.
    std::optional<TemporaryFileGuard> guard;
    std::unique_ptr<RunWriter> writer;
    {
        const StopSignalsBlocked blocked;  // one arriving between creating the file and arming waits
        if (!args.out.empty()) writer = std::make_unique<RunWriter>(args.out, args.frames);
        guard.emplace(writer.get());
    }
    ProgressLine progress;
    RunOptions run_options;
    run_options.writer = writer.get();
    run_options.on_output = [&progress](double time, double duration) { progress.update_time(time, duration); };
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
    // No CLI::ExistingFile check: load_scene names a missing file or a directory itself, and
    // fails with the documented exit status 1 (CLI11's checks exit with 105).
    cmd->add_option("scene", args->scene_path, "Scene file (TOML)")->required();
    cmd->add_option("-b,--backend", args->backend, "Backend name (see `collide backends`)")->capture_default_str();
    cmd->add_option("-o,--out", args->out, "HDF5 output file (written atomically)");
    cmd->add_flag("--frames", args->frames, "Also store positions and velocities at every output time");
    add_backend_options(*cmd, args->options);
    add_set_option(*cmd, args->overrides);
    cmd->callback([args] { execute(*args); });
}

}  // namespace collide::cli
