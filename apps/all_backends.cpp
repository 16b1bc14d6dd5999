// The list of backends compiled into collide. Adding a backend = one entry here; the
// command line, validation runner, benchmark and conformance tests pick it up from this list.
#include "box2d/box2d_solver.h"
#include "core/backend_registry.h"
#include "reference/step_solver.h"

namespace collide {

const std::vector<BackendInfo>& all_backends() {
    static const std::vector<BackendInfo> backends = {
        {"step", "double", "time-stepped rules of seeds 000/001, serial reference",
         [](const Scene&) -> std::optional<std::string> { return std::nullopt; },
         [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<StepSolver>(); }},
        {"box2d", "float", "Box2D 2.4 world of circle bodies, the baseline", box2d_supports,
         [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<Box2dSolver>(); }},
    };
    return backends;
}

}  // namespace collide
