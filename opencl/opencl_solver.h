// The `opencl` backend: the stepping rules of docs/stepping-rules.md as OpenCL kernels
// (seed 000), in float, or in double on devices with fp64 (`--real double`).
//
// Options (BackendOptions):
//   real            "float" (default) or "double"
//   device          OpenCL device: index or name substring (see `collide devices`)
//   extra["grid"]   "host": the grid is built on the host by counting sort and uploaded every
//                   step (seed 000's design); "device": built by kernels (kernels/grid.cl).
//                   Default: the one measured faster for the device type and N
//                   (docs/opencl-backend.md): device, except host below N = 5e4 on a CPU.
//   extra["local_size"]  work-group size of the per-disk kernels (default: the driver's choice)
// A scene file can set `grid` and `local_size` too, in its [backend.opencl] table; options
// given here take precedence.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "cl_devices.h"
#include "core/solver.h"

namespace collide::opencl {

std::unique_ptr<Solver> make_opencl_solver(const BackendOptions& options);

// The -D flags and other options the solver builds its kernels with for this scene.
std::string kernel_build_options(const Scene& scene, const ParticleState<double>& initial, bool real_double,
                                 const DeviceEntry& device);

}  // namespace collide::opencl
