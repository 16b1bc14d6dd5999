// measure_frames: runs one backend on one scene for a number of fixed-timestep frames
// (ParticleBox's headless benchmark) and reports the throughput and the time per phase.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "bench_suite.h"
#include "core/backend_registry.h"
#include "bench_gas.h"

namespace collide::bench {

struct FrameTiming {
    bool stopped = false;               // the first frame exceeded the per-frame limit
    double first_frame_seconds = 0;     // the warm-up frame (not in the figures below)
    double seconds = 0;                 // the measured frames
    double cpu_seconds = 0;             // processor time of the measured frames, all threads
    double particle_steps_per_second = 0;
    double cpu_ns_per_particle_step = 0;  // cpu_seconds per particle-step, in ns
    std::map<std::string, double> phase_ms_per_frame;  // from SolverStats.phase_seconds
    std::string threads;                // as the backend reports it, or as requested
    std::map<std::string, double> counters;        // the solver's named counters after the run
    std::map<std::string, double> counters_gained; // their increase over the measured frames
};

// One warm-up frame, then `frames` timed frames (frame = one step dt of the scene). If the
// warm-up frame takes longer than frame_limit_seconds the run stops there (stopped = true).
FrameTiming measure_frames(const BackendInfo& backend, const BackendOptions& options, const GasCase& gas,
                           int frames, double frame_limit_seconds);

// Adds the timing to a report row: particle_steps_per_s, ns_per_particle_step, seconds,
// cpu_ns_per_particle_step (processor time of every thread: the ns of a core a disk-step
// costs, which other jobs on a loaded machine do not inflate), threads and one
// ms_per_frame_<phase> column per phase.
void add_timing(Row& row, const FrameTiming& t, std::int64_t n);

}  // namespace collide::bench
