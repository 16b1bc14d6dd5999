// Solver: the interface every backend implements (event, step, cpu, opencl, box2d).
//
// Life cycle: supports(scene) -> load(scene, initial state) -> advance_to(t1) -> read_state
// -> advance_to(t2) -> ... Times are absolute simulation times and never decrease.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "particle_state.h"
#include "scene.h"

namespace collide {

// What a backend did so far. Counters a backend does not have stay 0; backend-specific
// figures (pressure, translation-cap hits, ...) go into `counters`.
struct SolverStats {
    std::int64_t steps = 0;       // time steps (stepped backends) or events (event-driven)
    std::int64_t contacts = 0;    // pair contacts resolved (stepped) or collisions (event)
    std::map<std::string, double> phase_seconds;  // wall time per phase, e.g. "grid", "collide"
    std::map<std::string, double> counters;       // named extra statistics
};

// Options chosen on the command line or by a validation case, not by the scene.
struct BackendOptions {
    int threads = 0;              // 0: the backend's default (all cores)
    std::string real;             // "", "float" or "double" (backends that offer both)
    std::string device;           // OpenCL device selector ("" = first)
    std::map<std::string, std::string> extra;  // backend-specific, e.g. {"grid", "device"}
};

class Solver {
public:
    virtual ~Solver() = default;
    virtual std::string name() const = 0;
    // Takes the scene and its initial state; throws std::runtime_error on bad input.
    virtual void load(const Scene& scene, const ParticleState<double>& initial) = 0;
    // Advances the simulation to absolute time t (t >= current time).
    virtual void advance_to(double t) = 0;
    // Writes the current state, in double, into `out` (resized as needed).
    virtual void read_state(ParticleState<double>& out) const = 0;
    virtual double time() const = 0;
    virtual SolverStats stats() const = 0;
    // Free-form provenance for output files (device name, build options, ...).
    virtual std::map<std::string, std::string> provenance() const { return {}; }
};

}  // namespace collide
