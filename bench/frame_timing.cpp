#include "frame_timing.h"

namespace collide::bench {

FrameTiming measure_frames(const BackendInfo& backend, const BackendOptions& options, const GasCase& gas,
                           int frames, double frame_limit_seconds) {
    FrameTiming t;
    auto solver = backend.create(options);
    solver->load(gas.scene, gas.initial);
    const double dt = gas.scene.run.dt;
    t.first_frame_seconds = time_seconds([&] { solver->advance_to(dt); });
    const auto prov = solver->provenance();
    const auto it = prov.find(backend.name + ".threads");
    t.threads = it != prov.end() ? it->second : (options.threads > 0 ? std::to_string(options.threads) : "default");
    if (t.first_frame_seconds > frame_limit_seconds) {
        t.stopped = true;
        return t;
    }
    const SolverStats before = solver->stats();
    const double cpu_start = cpu_seconds();
    t.seconds = time_seconds([&] { solver->advance_to(dt * double(1 + frames)); });
    t.cpu_seconds = cpu_seconds() - cpu_start;
    const SolverStats after = solver->stats();
    t.counters = after.counters;
    for (const auto& [name, value] : after.counters) {
        const auto b = before.counters.find(name);
        t.counters_gained[name] = value - (b == before.counters.end() ? 0.0 : b->second);
    }
    const double n = double(gas.initial.size());
    t.particle_steps_per_second = n * frames / t.seconds;
    t.cpu_ns_per_particle_step = 1e9 * t.cpu_seconds / (n * frames);
    for (const auto& [phase, seconds] : after.phase_seconds) {
        const auto b = before.phase_seconds.find(phase);
        t.phase_ms_per_frame[phase] = 1e3 * (seconds - (b == before.phase_seconds.end() ? 0.0 : b->second)) / frames;
    }
    return t;
}

void add_timing(Row& row, const FrameTiming& t, std::int64_t n) {
    row["threads"] = t.threads;
    row["seconds"] = t.seconds;
    row["particle_steps_per_s"] = t.particle_steps_per_second;
    row["ns_per_particle_step"] = 1e9 / t.particle_steps_per_second;
    row["cpu_ns_per_particle_step"] = t.cpu_ns_per_particle_step;
    row["n"] = n;
    for (const auto& [phase, ms] : t.phase_ms_per_frame) row["ms_per_frame_" + phase] = ms;
}

}  // namespace collide::bench
