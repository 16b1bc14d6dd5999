// Solver: the interface every backend implements (event, step, cpu, opencl, box2d).
//
// Life cycle: supports(scene) -> load(scene, initial state) -> advance_to(t1) -> read_state
// -> advance_to(t2) -> ... Times are absolute simulation times and never decrease.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/particle_state.h"
#include "core/scene/scene.h"

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

// Thrown by a backend that learns only when it runs that it cannot run a scene (an outside
// solver answering "refuse": external/external_solver.h). Like a `supports()` refusal, the case
// is then left out with the reason, not failed.
class SceneRefused : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
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
    // The times advance_to will be called with, in order (run_scene says so before its loop).
    // A hint: a solver that computes them all at once (an outside program, one call per run)
    // uses it; the others ignore it, and every solver must still accept other times.
    virtual void plan_outputs(const std::vector<double>& /*times*/) {}
    virtual double time() const = 0;
    virtual SolverStats stats() const = 0;
    // Free-form provenance for output files (device name, build options, ...).
    virtual std::map<std::string, std::string> provenance() const { return {}; }
};

}  // namespace collide
