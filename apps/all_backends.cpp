// The list of backends compiled into collide. Adding a backend = one entry here; the
// command line, validation runner, benchmark and conformance tests pick it up from this list.
#include "core/backend_registry.h"
#include "opencl/opencl_solver.h"
#include "reference/step_solver.h"

namespace collide {

const std::vector<BackendInfo>& all_backends() {
    static const std::vector<BackendInfo> backends = {
        {"step", "double", "time-stepped rules of seeds 000/001, serial reference",
         [](const Scene&) -> std::optional<std::string> { return std::nullopt; },
         [](const BackendOptions&) -> std::unique_ptr<Solver> { return std::make_unique<StepSolver>(); }},
        {"opencl", "float|double", "stepping rules as OpenCL kernels (seed 000), float or --real double",
         [](const Scene&) -> std::optional<std::string> { return std::nullopt; }, opencl::make_opencl_solver},
    };
    return backends;
}

}  // namespace collide
