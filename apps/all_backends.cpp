// The list of backends compiled into collide. Adding a backend = one entry here; the
// command line, validation runner, benchmark and conformance tests pick it up from this list.
#include "box2d/box2d_solver.h"
#include "chipmunk/chipmunk_solver.h"
#include "core/backend_registry.h"
#include "cpu/cpu_solver.h"
#include "opencl/opencl_solver.h"
#include "reference/event/event_solver.h"
#include "reference/plain_event_solver.h"
#include "reference/step_solver.h"
#include "sampling/ecmc_sampler.h"
#include "sampling/metropolis_sampler.h"

#include <stdexcept>

namespace collide {

const std::vector<BackendInfo>& all_backends() {
    // What each method conserves up to rounding where the scene's physics does: an exact
    // collision conserves momentum and energy; the stepped rules exchange equal and opposite
    // impulses (momentum) but lose or gain energy when a disk takes two impulses from one
    // Jacobi snapshot (docs/stepping-rules.md, "Energy at e = 1").
    const std::vector<std::string> momentum_and_energy = {"momentum", "energy"}, momentum = {"momentum"};
    const std::string either_rule = "collide-first|integrate-first";  // the scene's [run] order
    // The limits of a game engine's sequential-impulse contact solver (Box2D, Chipmunk): derived
    // for Box2D from its restitution threshold and linear slop (docs/validation.md, "box2d").
    // overlap_beyond_step: the slop (0.5 % of the mean diameter) is overlap the contact solver
    // leaves alone, even in a pair at rest; relative to a pair's contact distance that is at
    // most 1 % for disks of half the mean size.
    const std::vector<std::pair<std::string, double>> sequential_impulse_limits = {
        {"momentum_drift", 1e-4}, {"energy_drift", 5e-2}, {"max_overlap", 0.25}, {"mean_overlap", 0.05},
        {"overlapping_pairs_per_disk", 1.0}, {"overlap_beyond_step", 1e-2}, {"wall_penetration", 0.25},
        {"trajectory_error", 1.0}};
    static const std::vector<BackendInfo> backends = {
        {.name = "event", .precision = "double",
         .description = "exact event-driven hard disks (EDMD), serial: the reference", .supports = &EventSolver::supports,
         .create = [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<EventSolver>(); },
         .exact = true, .conserves = momentum_and_energy},
        {.name = "event-plain", .precision = "double",
         .description = "the same exact event-driven method written plainly (binary heap, cell list), serial",
         .supports = &PlainEventSolver::supports,
         .create = [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<PlainEventSolver>(); },
         .in_all = false,  // not in a suite's "all" (BackendInfo::in_all)
         .exact = true, .conserves = momentum_and_energy},
        {.name = "step", .precision = "double",
         .description = "the two stepping rules (collide-first, integrate-first) in double, serial: the readable reference",
         .supports = [](const Scene&) -> std::optional<std::string> { return std::nullopt; },
         .create = [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<StepSolver>(); },
         .rule = either_rule, .conserves = momentum},
        {.name = "cpu", .precision = "float",
         .description = "the same rules in float, multi-threaded (OpenMP), loops specialised on the scene's features",
         .supports = [](const Scene&) -> std::optional<std::string> { return std::nullopt; },
         .create = [](const BackendOptions& o) -> std::unique_ptr<Solver> { return std::make_unique<cpu::CpuSolver>(o); },
         .rule = either_rule, .conserves = momentum},
        {.name = "opencl", .precision = "float|double", .description = "the same rules as OpenCL kernels, float or --real double",
         .supports = [](const Scene&) -> std::optional<std::string> { return std::nullopt; },
         .create = opencl::make_opencl_solver, .rule = either_rule, .conserves = momentum, .one_device = true},
        // Box2D is neither exact nor the stepping rules: its limits are its own, derived from its
        // sequential impulses, restitution threshold and linear slop (docs/validation.md, "box2d").
        {.name = "box2d", .precision = "float", .description = "Box2D 2.4 world of circle bodies, the baseline",
         .supports = box2d_supports,
         .create = [](const BackendOptions& o) -> std::unique_ptr<Solver> { return std::make_unique<Box2dSolver>(o); },
         .sweeps_iterations = true,
         .limits = sequential_impulse_limits},
        // Chipmunk2D, the other C engine people use: sequential impulses like Box2D, in double, with
        // no restitution threshold. Not in "all": it is one of the engines of the engines suite
        // (validation/suites/engines.toml, docs/engines.md), not a method the default suite judges.
        {.name = "chipmunk", .precision = "double", .description = "Chipmunk2D 7 space of circle bodies (Debian's libchipmunk)",
         .supports = chipmunk_supports,
         .create = [](const BackendOptions& o) -> std::unique_ptr<Solver> { return std::make_unique<ChipmunkSolver>(o); },
         .sweeps_iterations = true, .in_all = false,
         .limits = sequential_impulse_limits},
        // Samplers: configurations from the equilibrium measure, no time, no velocities
        // (docs/monte-carlo.md). Not in "all": the default suite keeps its time.
        {.name = "ecmc", .precision = "double",
         .description = "straight event-chain Monte Carlo (Bernard, Krauth, Wilson 2009), periodic, equal disks: a sampler",
         .supports = &EcmcSampler::supports,
         .create = [](const BackendOptions& o) -> std::unique_ptr<Solver> { return std::make_unique<EcmcSampler>(o); },
         .in_all = false, .sampler = true},
        {.name = "metropolis", .precision = "double",
         .description = "plain local Monte Carlo (one disk, uniform trial step, reject on overlap), walls or periodic: a sampler",
         .supports = &MetropolisSampler::supports,
         .create = [](const BackendOptions& o) -> std::unique_ptr<Solver> { return std::make_unique<MetropolisSampler>(o); },
         .in_all = false, .sampler = true},
    };
    return backends;
}

const BackendInfo* backend_if_built(const std::string& name) {
    for (const auto& b : all_backends())
        if (b.name == name) return &b;
    return nullptr;
}

const BackendInfo& find_backend(const std::string& name) {
    if (const BackendInfo* b = backend_if_built(name)) return *b;
    std::string names;
    for (const auto& b : all_backends()) names += (names.empty() ? "" : ", ") + b.name;
    throw std::invalid_argument("unknown backend '" + name + "'; available: " + names);
}

}  // namespace collide
