// The list of backends compiled into collide. Adding a backend = one entry here; the
// command line, validation runner, benchmark and conformance tests pick it up from this list.
#include "box2d/box2d_solver.h"
#include "core/backend_registry.h"
#include "cpu/cpu_solver.h"
#include "opencl/opencl_solver.h"
#include "reference/event/event_solver.h"
#include "reference/plain_event_solver.h"
#include "reference/step_solver.h"

#include <stdexcept>

namespace collide {

const std::vector<BackendInfo>& all_backends() {
    static const std::vector<BackendInfo> backends = {
        {.name = "event", .precision = "double",
         .description = "exact event-driven hard disks (EDMD), serial: the reference", .supports = &EventSolver::supports,
         .create = [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<EventSolver>(); },
         .event_driven = true},
        {.name = "event-plain", .precision = "double",
         .description = "the same exact event-driven method written plainly (binary heap, cell list), serial",
         .supports = &PlainEventSolver::supports,
         .create = [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<PlainEventSolver>(); },
         .in_all = false,  // not in a suite's "all" (BackendInfo::in_all)
         .event_driven = true},
        {"step", "double", "the two stepping rules (collide-first, integrate-first) in double, serial: the readable reference",
         [](const Scene&) -> std::optional<std::string> { return std::nullopt; },
         [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<StepSolver>(); }, false},
        {"cpu", "float", "the same rules in float, multi-threaded (OpenMP), loops specialised on the scene's features",
         [](const Scene&) -> std::optional<std::string> { return std::nullopt; },
         [](const BackendOptions& o) -> std::unique_ptr<Solver> { return std::make_unique<cpu::CpuSolver>(o); }, false},
        {"opencl", "float|double", "the same rules as OpenCL kernels, float or --real double",
         [](const Scene&) -> std::optional<std::string> { return std::nullopt; }, opencl::make_opencl_solver, false},
        {"box2d", "float", "Box2D 2.4 world of circle bodies, the baseline", box2d_supports,
         [](const BackendOptions& o) -> std::unique_ptr<Solver> { return std::make_unique<Box2dSolver>(o); }, true},
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
