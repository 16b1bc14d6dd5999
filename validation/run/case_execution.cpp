#include "validation/run/case_execution.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>

#include "core/io/provenance.h"
#include "core/run_driver.h"
#include "core/scene/scene_loader.h"
#include "core/metrics.h"
#include "validation/judge/observables.h"
#include "validation/compare/phase_shift.h"
#include "validation/compare/predictability_horizon.h"
#include "validation/run/twin_runs.h"

namespace collide::validation {
namespace {

Snapshot snapshot_of(const ParticleState<double>& s) { return {s.x, s.y, s.vx, s.vy, s.radius}; }

bool feeds(const SuiteScene& entry, const char* physics_row) {
    return std::find(entry.physics.begin(), entry.physics.end(), physics_row) != entry.physics.end();
}

// The solver's collision count and collision virial at the first output time of the second
// half: the physics rows (physics_rows.h) measure over the second half alone, the first being
// the approach to equilibrium from the generated state.
void record_half(const SolverStats& stats, double time, std::map<std::string, double>& counters) {
    counters["time_at_half"] = time;
    counters["contacts_at_half"] = double(stats.contacts);
    if (const auto v = stats.counters.find("virial_sum"); v != stats.counters.end()) counters["virial_sum_at_half"] = v->second;
}

// A short run on a separate solver before the timed one, so that the timed run does not pay
// for first-touch page faults, lazy initialisation (OpenCL program builds) or cold caches.
double warm_up(const Scene& scene, const BackendInfo& backend, const CaseSpec& spec,
               const ParticleState<double>& initial, double fraction) {
    if (fraction <= 0) return 0;
    const auto start = std::chrono::steady_clock::now();
    auto solver = backend.create(case_backend_options(spec));
    solver->load(scene, initial);
    const double dt = scene.run.dt;
    const double t = std::max(dt, std::round(fraction * scene.run.duration / dt) * dt);
    solver->advance_to(std::min(t, scene.run.duration));
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::map<std::string, std::string> file_attributes(const Scene& scene, const CaseSpec& spec,
                                                   const Solver& solver) {
    auto attributes = run_provenance(scene, spec.backend, solver);
    attributes["case_id"] = spec.id;
    return attributes;
}

// The case's cost: the time in advance_to(), or, for an outside solver that states its own
// stepping time in every call (protocol 2, `seconds`), that time: its calls' wall time also
// holds the program's start-up and file exchange (Node and a wasm engine: about 1.8 s a call),
// which is kept beside it as the counter call_wall_seconds.
double solver_cost_seconds(const RunResult& run) {
    const auto& c = run.stats.counters;
    const auto own = c.find("solver_seconds");
    if (own == c.end() || c.count("solver_seconds_missing")) return run.wall_seconds;
    return own->second;
}

void measure(const CaseSpec& spec, const CaseContext& ctx, CaseResult& result) {
    const Suite& suite = *ctx.suite;
    const SuiteScene& entry = suite.scenes[spec.scene_index];
    const Scene scene = case_scene(*ctx.scene, entry, spec);
    result.duration = scene.run.duration;
    result.dt = scene.run.dt;
    result.substeps = scene.run.substeps;
    const ParticleState<double> initial = case_initial_state(scene, entry, spec.seed);
    result.disks = initial.size();
    for (std::size_t i = 0; i < initial.size(); ++i)
        if (!initial.is_stone(i)) result.total_mass += initial.mass[i];
    result.initial = snapshot_of(initial);

    result.warmup_seconds = warm_up(scene, *ctx.backend, spec, initial, suite.warmup_fraction);

    std::unique_ptr<RunWriter> writer;
    if (suite.output.hdf5) {
        std::filesystem::create_directories(ctx.output_dir + "/runs");
        result.hdf5_file = "runs/" + spec.id + ".h5";
        writer = std::make_unique<RunWriter>(ctx.output_dir + "/" + result.hdf5_file,
                                             stores_frames(suite, entry));
    }
    const bool record_trajectory = initial.size() <= suite.output.max_trajectory_disks;
    const bool contact_shell_z = entry.comparison == Comparison::statistics || feeds(entry, "equation_of_state");
    auto solver = ctx.backend->create(case_backend_options(spec));
    bool half_recorded = false;
    RunOptions options;
    options.writer = writer.get();
    options.on_state = [&](const ParticleState<double>& state, const Metrics& m) {
        result.series.push_back(m);
        if (record_trajectory) {
            result.trajectory_time.push_back(m.time);
            result.trajectory.push_back(snapshot_of(state));
        }
        // Equilibrium observables from the second half only: the first half is the approach
        // to equilibrium from the generated initial state.
        if (contact_shell_z && m.time >= 0.5 * scene.run.duration && m.nonfinite == 0)
            result.compressibility.push_back(compressibility_factor(scene, state));
        if (!half_recorded && m.time >= 0.5 * scene.run.duration) {
            record_half(solver->stats(), m.time, result.counters);
            half_recorded = true;
        }
    };
    try {
        const RunResult run = run_scene(scene, *solver, initial, options);
        result.wall_seconds = solver_cost_seconds(run);
        result.steps = run.stats.steps;
        result.contacts = run.stats.contacts;
        result.phase_seconds = run.stats.phase_seconds;
        for (const auto& [name, value] : run.stats.counters) result.counters[name] = value;
        if (result.wall_seconds != run.wall_seconds) result.counters["call_wall_seconds"] = run.wall_seconds;
        result.final_state = snapshot_of(run.final_state);
        auto depths = overlap_depths(scene, run.final_state);
        if (depths.size() > suite.output.max_overlap_samples) depths.resize(suite.output.max_overlap_samples);
        result.overlap_depths = std::move(depths);
    } catch (const SceneRefused&) {
        throw;  // left out, not failed: execute_case
    } catch (const std::exception& e) {
        // The metrics up to the failure are kept (they show how it went wrong).
        result.status = RunStatus::error;
        result.diagnostic = e.what();
        const SolverStats stats = solver->stats();
        result.steps = stats.steps;
        result.contacts = stats.contacts;
    }
    result.provenance = solver->provenance();
    // The reference of a trajectory comparison measures its own predictability horizon: its
    // twins run after the timed run, untimed (predictability_horizon.h).
    if (spec.reference && entry.comparison == Comparison::trajectory && record_trajectory && result.finished())
        result.twin_separation = twin_separation(scene, *ctx.backend, case_backend_options(spec), initial,
                                                 result.trajectory, spec.seed, horizon_twins);
    if (writer) {
        writer->write_attributes(file_attributes(scene, spec, *solver));
        writer->commit();
    }
}

}  // namespace

BackendOptions case_backend_options(const CaseSpec& spec) {
    BackendOptions options;
    if (spec.iterations) options.extra["iterations"] = std::to_string(*spec.iterations);
    return options;
}

ParticleState<double> case_initial_state(const Scene& scene, const SuiteScene& entry, std::uint64_t seed) {
    ParticleState<double> initial = generate_initial_state(scene);
    if (entry.comparison == Comparison::trajectory) advance_free_flight(scene, initial, phase_shift(seed, scene.run.dt));
    return initial;
}

CaseResult execute_case(const CaseSpec& spec, const CaseContext& ctx) {
    CaseResult result;
    result.spec = spec;
    if (!spec.left_out.empty()) {
        result.status = RunStatus::left_out;
        result.diagnostic = spec.left_out;
        return result;
    }
    try {
        measure(spec, ctx, result);
    } catch (const SceneRefused& e) {
        // The backend found only when it ran that it cannot run this scene (an outside solver's
        // "refuse"): the case is left out with its reason, as a supports() refusal would be.
        result = CaseResult{};
        result.spec = spec;
        result.status = RunStatus::left_out;
        result.diagnostic = e.what();
    } catch (const std::exception& e) {
        result.status = RunStatus::error;
        result.diagnostic = e.what();
    }
    return result;
}

}  // namespace collide::validation
