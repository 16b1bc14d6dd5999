// The per-particle loops of the `cpu` backend, one function per phase, each a template on the
// features it touches (feature_set.h) and each working on a range [begin, end) of particles
// so that parallel_for can hand out chunks. Every function writes only the slots of the
// particles in its range: that is what makes them safe to run in parallel without locks.
//
// The physics is not here: every pair goes through the shared contact law
// (core/contact_law.h via ContactLaw<float>) and every wall through WallLaw<float>, the same
// text `step` and the OpenCL kernels compile.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cell_list.h"
#include "core/particle_state.h"
#include "core/stepping_laws.hpp"

namespace collide::cpu {

// The scene's parameters in float, read by the kernels.
struct PhaseParams {
    float restitution = 1, friction = 0, wall_restitution = 1;
    float gravity_x = 0, gravity_y = 0, damping = 0;
    float radius = 0;  // the common radius when every disk has the same one
    float xmin = 0, ymin = 0, xmax = 1, ymax = 1, width = 1, height = 1;
};

// Per-particle corrections of one Jacobi contact pass (seed 001 keeps them in the then-unused
// acceleration arrays; here they have their own arrays).
struct Corrections {
    float* dx;
    float* dy;
    float* dvx;
    float* dvy;
};

// Velocity update v += (g - gamma v) h, the field accelerations and linear drag of both rules,
// with the terms a scene does not use compiled out. Stones (inverse mass 0) are kinematic.
template <bool Gravity, bool Damping, bool Stones>
inline void kick(float& vx, float& vy, float inv_mass, const PhaseParams& p, float h) {
    if constexpr (Stones)
        if (inv_mass == 0.0f) return;
    if constexpr (Damping) {
        vx += (p.gravity_x - p.damping * vx) * h;
        vy += (p.gravity_y - p.damping * vy) * h;
    } else if constexpr (Gravity) {
        vx += p.gravity_x * h;
        vy += p.gravity_y * h;
    }
}

// World bounds: periodic wrap, or reflecting walls with wall restitution. Stones stay put.
template <bool Stones, bool Periodic>
inline void apply_bounds(float& x, float& y, float& vx, float& vy, float radius, float inv_mass,
                         const PhaseParams& p) {
    if constexpr (Stones)
        if (inv_mass == 0.0f) return;
    if constexpr (Periodic) {
        x = WallLaw<float>::wrap(x, p.xmin, p.width);
        y = WallLaw<float>::wrap(y, p.ymin, p.height);
    } else {
        WallLaw<float>::reflect_axis(&x, &vx, radius, p.xmin, p.xmax, p.wall_restitution);
        WallLaw<float>::reflect_axis(&y, &vy, radius, p.ymin, p.ymax, p.wall_restitution);
    }
}

// Integrate-first, phases 1-3: field accelerations, velocity with damping, then position with
// the new velocity (semi-implicit Euler, seed 001).
template <bool Gravity, bool Damping, bool Stones>
std::int64_t integrate_range(ParticleState<float>& s, const PhaseParams& p, float h, std::size_t begin,
                             std::size_t end) {
    float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float* inv_mass = s.inv_mass.data();
    for (std::size_t i = begin; i < end; ++i) {
        if constexpr (Stones)
            if (inv_mass[i] == 0.0f) continue;
        kick<Gravity, Damping, false>(vx[i], vy[i], 1.0f, p, h);
        x[i] += vx[i] * h;
        y[i] += vy[i] * h;
    }
    return 0;
}

// The one-sided Jacobi contact pass (phase 5 of integrate-first, first phase of collide-first).
// For each disk i of the range: sum the contact law's share of disk i over every neighbour j
// in the fixed order of the cell list, and store the sum in i's correction slots. Reads the
// state, writes only corrections[i]: disk j computes the mirror image for itself. Returns the
// number of contacts, each pair counted once (by its lower index, or by the moving disk when
// the other is a stone, which never runs the loop).
template <bool Friction, bool Stones, bool UniformRadius, bool Periodic>
std::int64_t collide_range(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p,
                           Corrections out, std::size_t begin, std::size_t end) {
    const float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    const std::uint32_t* index = grid.sorted_index();
    // Constant zero friction lets the compiler drop the law's friction branch entirely.
    const float mu = Friction ? p.friction : 0.0f;
    std::int64_t contacts = 0;
    for (std::size_t i = begin; i < end; ++i) {
        float dx = 0, dy = 0, dvx = 0, dvy = 0;
        const float wi = inv_mass[i];
        if (!Stones || wi != 0.0f) {  // a stone's share is always zero
            const float xi = x[i], yi = y[i], vxi = vx[i], vyi = vy[i];
            const float ri = UniformRadius ? p.radius : radius[i];
            grid.for_each_neighbour_range<Periodic>(xi, yi, [&](std::uint32_t k0, std::uint32_t k1) {
                for (std::uint32_t k = k0; k < k1; ++k) {
                    const std::uint32_t j = index[k];
                    float sep_x = xi - x[j], sep_y = yi - y[j];
                    if constexpr (Periodic) {
                        sep_x = WallLaw<float>::minimum_image(sep_x, p.width);
                        sep_y = WallLaw<float>::minimum_image(sep_y, p.height);
                    }
                    const float contact = UniformRadius ? ri + ri : ri + radius[j];
                    // Squared-distance reject first (seed 001): no square root, no law call.
                    // Disk i itself (distance 0) passes it and is skipped by the index test.
                    if (sep_x * sep_x + sep_y * sep_y >= contact * contact || j == i) continue;
                    const auto d = ContactLaw<float>::delta(sep_x, sep_y, vxi - vx[j], vyi - vy[j], contact,
                                                            wi, inv_mass[j], p.restitution, mu);
                    dx += d.dx;
                    dy += d.dy;
                    dvx += d.dvx;
                    dvy += d.dvy;
                    if (i < j || (Stones && inv_mass[j] == 0.0f)) ++contacts;
                }
            });
        }
        out.dx[i] = dx;
        out.dy[i] = dy;
        out.dvx[i] = dvx;
        out.dvy[i] = dvy;
    }
    return contacts;
}

// Integrate-first, phase 6: apply the corrections, then the world bounds.
template <bool Stones, bool Periodic>
std::int64_t correct_range(ParticleState<float>& s, Corrections c, const PhaseParams& p, std::size_t begin,
                           std::size_t end) {
    float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    for (std::size_t i = begin; i < end; ++i) {
        x[i] += c.dx[i];
        y[i] += c.dy[i];
        vx[i] += c.dvx[i];
        vy[i] += c.dvy[i];
        apply_bounds<Stones, Periodic>(x[i], y[i], vx[i], vy[i], radius[i], inv_mass[i], p);
    }
    return 0;
}

// Collide-first, after the contact pass: apply the corrections, explicit Euler (position with
// the velocity before this step's forces, then the forces), then the world bounds; the same
// order of operations as StepSolver::step_collide_first, fused into one pass over memory.
template <bool Gravity, bool Damping, bool Stones, bool Periodic>
std::int64_t correct_and_integrate_range(ParticleState<float>& s, Corrections c, const PhaseParams& p, float dt,
                                         std::size_t begin, std::size_t end) {
    float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    for (std::size_t i = begin; i < end; ++i) {
        x[i] += c.dx[i];
        y[i] += c.dy[i];
        vx[i] += c.dvx[i];
        vy[i] += c.dvy[i];
        if constexpr (Stones)
            if (inv_mass[i] == 0.0f) continue;
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
        kick<Gravity, Damping, false>(vx[i], vy[i], 1.0f, p, dt);
        apply_bounds<false, Periodic>(x[i], y[i], vx[i], vy[i], radius[i], 1.0f, p);
    }
    return 0;
}

}  // namespace collide::cpu
