// The `opencl` backend: the stepping rules of docs/stepping-rules.md as OpenCL kernels
// in float, or in double on devices with fp64 (`--real double`).
//
// Options (BackendOptions):
//   real            "float" (default) or "double"
//   device          OpenCL device: index or name substring (see `collide devices`)
//   extra["grid"]   "host": the grid is built on the host by counting sort and uploaded every
//                   step (cheap for few disks on a CPU device); "device": built by kernels (kernels/grid.cl);
//                   "group": one work-group builds it and runs many steps per launch
//                   (kernels/group_steps.cl). Default: the one measured faster for the device
//                   type and N (docs/opencl-backend.md): group up to N = 4096, then device,
//                   except host below N = 5e4 on a CPU.
//   extra["local_size"]  work-group size of the per-disk kernels (default: the driver's choice)
//   extra["sort_interval"]  K >= 0: at every K-th grid build (one per step, or per sub-step of
//                   the integrate-first rule) move the disks into cell order on the device
//                   (kernels/reorder.cl), so that the neighbours a contact pass reads lie next
//                   to each other in memory; 0 = never. Default 1. Results do not depend on K:
//                   cells list their disks by scene index either way, and read_state returns
//                   the scene's order. grid = "group" never reorders.
// A scene file can set `grid`, `local_size` and `sort_interval` too, in its [backend.opencl]
// table; options given here take precedence.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "cl_devices.h"
#include "core/solver.h"

namespace collide::opencl {

std::unique_ptr<Solver> make_opencl_solver(const BackendOptions& options);

// The largest N the default grid choice gives grid = "group" (one work-group, many steps per
// launch): below it launches cost more than the work.
inline constexpr std::size_t group_grid_up_to = 4096;

// The -D flags and other options the solver builds its kernels with for this scene.
std::string kernel_build_options(const Scene& scene, const ParticleState<double>& initial, bool real_double,
                                 const DeviceEntry& device);

}  // namespace collide::opencl
