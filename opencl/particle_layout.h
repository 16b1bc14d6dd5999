// C++ access to the particle layout shared with the kernels (particle_layout.cl.h), once per
// real type, with the layout checked at compile time. The kernels' own sizes are checked at
// run time against these (OpenclSolver::load runs kernel `layout_probe`).
#pragma once

#include <cstddef>

namespace collide::opencl {
namespace layout_float {
using Real = float;
#undef COLLIDE_PARTICLE_LAYOUT_H
#include "particle_layout.cl.h"
}  // namespace layout_float
namespace layout_double {
using Real = double;
#undef COLLIDE_PARTICLE_LAYOUT_H
#include "particle_layout.cl.h"
}  // namespace layout_double

template <typename Real> struct Layout;
template <> struct Layout<float> {
    using Particle = layout_float::Particle;
    using StepParams = layout_float::StepParams;
};
template <> struct Layout<double> {
    using Particle = layout_double::Particle;
    using StepParams = layout_double::StepParams;
};

// 32 bytes per particle in float, aligned to 32 (one aligned memory transaction); twice that in double.
static_assert(sizeof(layout_float::Particle) == 32 && alignof(layout_float::Particle) == 32);
static_assert(sizeof(layout_double::Particle) == 64 && alignof(layout_double::Particle) == 64);
static_assert(offsetof(layout_float::Particle, vx) == 8 && offsetof(layout_float::Particle, radius) == 20);
// 14 Reals then 8 ints, no padding anywhere.
static_assert(sizeof(layout_float::StepParams) == 14 * 4 + 8 * 4);
static_assert(sizeof(layout_double::StepParams) == 14 * 8 + 8 * 4);

}  // namespace collide::opencl
