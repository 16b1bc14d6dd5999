// The kernels' StepParams for a scene, and the -D flags that select the scene's features.
#pragma once

#include <string>

#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "core/scene/scene_features.h"
#include "core/uniform_grid.h"
#include "particle_layout.h"

namespace collide::opencl {

// The -D flags of kernels/prelude.cl for this scene's features (core/scene/scene_features.h): a
// kernel pays only for what it uses. With COLLIDE_UNIFORM_RADIUS the kernels use one constant
// contact distance.
inline std::string feature_flags(const Scene& scene, const ParticleState<double>& s, bool real_double) {
    const SceneFeatures f = scene_features(scene, s);
    std::string flags;
    if (real_double) flags += " -D COLLIDE_REAL_DOUBLE";
    if (scene.run.order == StepOrder::integrate_first) flags += " -D COLLIDE_INTEGRATE_FIRST";
    if (f.periodic()) flags += " -D COLLIDE_PERIODIC";
    if (f.gravity) flags += " -D COLLIDE_GRAVITY";
    if (f.damping) flags += " -D COLLIDE_DAMPING";
    if (f.friction) flags += " -D COLLIDE_FRICTION";
    if (f.stones) flags += " -D COLLIDE_STONES";
    if (f.uniform_radius) flags += " -D COLLIDE_UNIFORM_RADIUS";
    return flags.empty() ? flags : flags.substr(1);
}

// Neighbour cell offsets along one axis, as UniformGrid::axis_offsets: {-1, 0, 1}, fewer on a
// periodic axis of under 3 cells (a cell must not be visited twice through the wrap).
inline void axis_offsets(bool periodic, std::int64_t cells, int& lo, int& hi) {
    lo = -1;
    hi = 1;
    if (periodic && cells == 2) lo = 0;
    if (periodic && cells == 1) lo = hi = 0;
}

// h: the kernels' step length (dt, or dt/substeps for the integrate-first rule).
template <typename Real>
typename Layout<Real>::StepParams make_step_params(const Scene& scene, const ParticleState<double>& s,
                                                   const UniformGrid<Real>& grid, double h) {
    typename Layout<Real>::StepParams p{};
    const World& w = scene.world;
    p.h = Real(h);
    p.restitution = Real(scene.physics.restitution);
    p.friction = Real(scene.physics.friction);
    p.wall_restitution = Real(scene.physics.wall_restitution);
    p.gravity_x = Real(scene.physics.gravity_x);
    p.gravity_y = Real(scene.physics.gravity_y);
    p.damping = Real(scene.physics.damping);
    p.xmin = Real(w.xmin);
    p.ymin = Real(w.ymin);
    p.xmax = Real(w.xmax);
    p.ymax = Real(w.ymax);
    // The same expressions as UniformGrid::configure, so both grids put a disk in one cell.
    p.inv_cell_w = Real(double(grid.cells_x()) / w.width());
    p.inv_cell_h = Real(double(grid.cells_y()) / w.height());
    const Real r = s.radius.empty() ? Real(0) : Real(s.radius.front());
    p.contact_distance = r + r;
    p.cells_x = int(grid.cells_x());
    p.cells_y = int(grid.cells_y());
    axis_offsets(scene.periodic(), grid.cells_x(), p.ox_lo, p.ox_hi);
    axis_offsets(scene.periodic(), grid.cells_y(), p.oy_lo, p.oy_hi);
    p.n = int(s.size());
    return p;
}

}  // namespace collide::opencl
