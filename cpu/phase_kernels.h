// The per-particle loops of the `cpu` backend, one function per phase, each a template on the
// features it touches (feature_set.h) and each working on a range [begin, end) of particles
// so that parallel_for can hand out chunks. Every function writes only the slots of the
// particles in its range: that is what makes them safe to run in parallel without locks.
//
// The physics is not here: every pair goes through the shared contact law
// (physics/contact_law.cl.h via ContactLaw<float>) and every wall through WallLaw<float>, the same
// text `step` and the OpenCL kernels compile.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "candidate_mask.h"
#include "cpu_cell_list.h"
#include "core/particle_state.h"
#include "physics/stepping_laws.h"

namespace collide::cpu {

// The scene's parameters in float, read by the kernels.
struct PhaseParams {
    float restitution = 1, friction = 0, wall_restitution = 1;
    float gravity_x = 0, gravity_y = 0, damping = 0;
    float radius = 0;  // the common radius when every disk has the same one
    float xmin = 0, ymin = 0, xmax = 1, ymax = 1, width = 1, height = 1;
};

// Two state slots, a < b: a pair of disks within reach (pair_list.h).
struct DiskPair {
    std::uint32_t a, b;
};

// Per-particle corrections of one Jacobi contact pass, in arrays of their own.
struct Corrections {
    float* dx;
    float* dy;
    float* dvx;
    float* dvy;
};

// The separation x_i - x_j of two disks, by the minimum image when the walls are periodic.
template <bool Periodic>
inline std::pair<float, float> separation(float xi, float yi, float xj, float yj, const PhaseParams& p) {
    float sep_x = xi - xj, sep_y = yi - yj;
    if constexpr (Periodic) {
        sep_x = WallLaw<float>::minimum_image(sep_x, p.width);
        sep_y = WallLaw<float>::minimum_image(sep_y, p.height);
    }
    return {sep_x, sep_y};
}

// Position and velocity of one disk, as a contact reads them.
struct DiskMotion {
    float x, y, vx, vy;
};

// Disk i's share of its contact with disk j: the shared contact law with the separation
// x_i - x_j and the relative velocity v_i - v_j. The one call sequence of every contact loop
// below (the cell path, the cell path in cell order and the pair list), so that all three
// give the same bits for the same pair.
template <bool Periodic>
inline ContactLaw<float>::Delta contact_share(const DiskMotion& i, const DiskMotion& j, float contact, float inv_mass_i,
                                              float inv_mass_j, const PhaseParams& p, float mu) {
    const auto [sep_x, sep_y] = separation<Periodic>(i.x, i.y, j.x, j.y, p);
    return ContactLaw<float>::delta(sep_x, sep_y, i.vx - j.vx, i.vy - j.vy, contact, inv_mass_i, inv_mass_j,
                                    p.restitution, mu);
}

// A disk's running sum of its shares, added in the order of the calls.
struct ShareSum {
    float dx = 0, dy = 0, dvx = 0, dvy = 0;
    void add(const ContactLaw<float>::Delta& d) {
        dx += d.dx;
        dy += d.dy;
        dvx += d.dvx;
        dvy += d.dvy;
    }
    void store(Corrections out, std::size_t i) const {
        out.dx[i] = dx;
        out.dy[i] = dy;
        out.dvx[i] = dvx;
        out.dvy[i] = dvy;
    }
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
// the new velocity (semi-implicit, symplectic Euler).
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

// The one-sided Jacobi contact pass (phase 5 of integrate-first, first phase of collide-first),
// over the rows [row_begin, row_end) of grid cells. For each disk i: sum the contact law's
// share of disk i over every neighbour j in the fixed order of the cell list, and store the
// sum in i's correction slots. Reads the state, writes only corrections[i]: disk j computes
// the mirror image for itself. Returns the number of contacts, each pair counted once (by
// its lower slot, or by the moving disk when the other is a stone, which never runs the loop).
//
// The candidates of disk i are the (at most six) slot ranges of its 3x3 cell neighbourhood,
// visited row by row from bottom to top, each range in slot order: the neighbour order of
// every sum. InCellOrder: the state itself is in cell order (CpuSolver's reorder), so slot k
// is disk k, the candidates are contiguous in every array, and collide_range_in_cell_order
// (below) tests them four at a time; otherwise slots map to disks through the index and the
// loop here tests them one by one.
template <bool Friction, bool Stones, bool UniformRadius, bool Periodic>
std::int64_t collide_range_in_cell_order(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p,
                                         Corrections out, std::size_t row_begin, std::size_t row_end);

template <bool Friction, bool Stones, bool UniformRadius, bool Periodic, bool InCellOrder>
std::int64_t collide_range(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p,
                          Corrections out, std::size_t row_begin, std::size_t row_end) {
    if constexpr (InCellOrder) {
        return collide_range_in_cell_order<Friction, Stones, UniformRadius, Periodic>(s, grid, p, out, row_begin,
                                                                                      row_end);
    }
    const float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    const std::uint32_t* index = grid.sorted_index();
    const std::uint32_t* cell_start = grid.cell_start();
    const std::int64_t cells_x = grid.cells_x();
    // Constant zero friction lets the compiler drop the law's friction branch entirely.
    const float mu = Friction ? p.friction : 0.0f;
    const float uniform_contact2 = (p.radius + p.radius) * (p.radius + p.radius);
    std::int64_t contacts = 0;
    // Per cell: all disks of a cell share one neighbourhood, computed once.
    for (std::int64_t cy = std::int64_t(row_begin); cy < std::int64_t(row_end); ++cy) {
        for (std::int64_t cx = 0; cx < cells_x; ++cx) {
            const std::uint32_t first = cell_start[cy * cells_x + cx], last = cell_start[cy * cells_x + cx + 1];
            if (first == last) continue;  // most cells are empty at low density
            SlotRange ranges[6];
            const int range_count = grid.neighbour_ranges<Periodic>(cx, cy, ranges);
            for (std::uint32_t a = first; a < last; ++a) {
                const std::uint32_t i = index[a];
                ShareSum sum;
                const float wi = inv_mass[i];
                if (!Stones || wi != 0.0f) {  // a stone's share is always zero
                    const DiskMotion mi{x[i], y[i], vx[i], vy[i]};
                    const float ri = UniformRadius ? p.radius : radius[i];
                    for (int r = 0; r < range_count; ++r) {
                        for (std::uint32_t b = ranges[r].begin; b < ranges[r].end; ++b) {
                            const std::uint32_t j = index[b];
                            const auto [sep_x, sep_y] = separation<Periodic>(mi.x, mi.y, x[j], y[j], p);
                            // Squared-distance reject first: no square root, no
                            // other load, no law call. Disk i itself (distance 0) passes it
                            // and is skipped by the slot test.
                            const float contact2 = UniformRadius ? uniform_contact2 : (ri + radius[j]) * (ri + radius[j]);
                            if (sep_x * sep_x + sep_y * sep_y >= contact2 || b == a) continue;
                            const float contact = UniformRadius ? ri + ri : ri + radius[j];
                            sum.add(contact_share<Periodic>(mi, {x[j], y[j], vx[j], vy[j]}, contact, wi, inv_mass[j], p, mu));
                            if (a < b || (Stones && inv_mass[j] == 0.0f)) ++contacts;
                        }
                    }
                }
                sum.store(out, i);
            }
        }
    }
    return contacts;
}

// The contact pass on a state in cell order, per disk rather than per cell, with the distance
// test four candidates at a time (candidate_mask.h). Disk a's cell column comes from its x by
// the grid's own rule (CellList::column_of: the same float operations on the same x as the
// sort, hence the same cell), so the loop walks the slots of a row of cells without visiting
// the empty cells between them. Its three neighbour ranges (rows cy-1, cy, cy+1, columns
// cx-1 .. cx+1) are read from the row starts fixed for the whole row; when each holds at most
// four slots (nearly always below area fraction 0.5) each is one block test, all three are
// tested before any branch, and one branch, almost never taken, leads to the contact law. The
// law then runs, in scalar and in slot order, for the candidates the masks report: the same
// pairs in the same order as the scalar loop above, hence bitwise the same sums. Longer
// ranges, and the columns where periodic walls split a row in two, take the general path:
// every range in blocks of four.
template <bool Friction, bool Stones, bool UniformRadius, bool Periodic>
std::int64_t collide_range_in_cell_order(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p,
                                         Corrections out, std::size_t row_begin, std::size_t row_end) {
    const float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    const std::uint32_t* cell_start = grid.cell_start();
    const std::int64_t cells_x = grid.cells_x();
    // The fast path needs three distinct rows and, with periodic walls, a column whose
    // neighbours do not wrap.
    const bool periodic_fast = grid.cells_x() >= 3 && grid.cells_y() >= 3;
    const float mu = Friction ? p.friction : 0.0f;
    CandidateQuery q{0, 0, 0, (p.radius + p.radius) * (p.radius + p.radius), p.width, p.height,
                     x, y, UniformRadius ? nullptr : radius, std::uint32_t(s.size())};
    std::int64_t contacts = 0;
    for (std::int64_t cy = std::int64_t(row_begin); cy < std::int64_t(row_end); ++cy) {
        const std::uint32_t row_first = cell_start[cy * cells_x], row_last = cell_start[(cy + 1) * cells_x];
        const std::uint32_t *below = grid.row_start<Periodic>(cy - 1), *own = grid.row_start<Periodic>(cy),
                            *above = grid.row_start<Periodic>(cy + 1);
        for (std::uint32_t a = row_first; a < row_last; ++a) {
            ShareSum sum;
            const float wi = inv_mass[a];
            if (!Stones || wi != 0.0f) {  // a stone's share is always zero
                const DiskMotion ma{x[a], y[a], vx[a], vy[a]};
                const float ri = UniformRadius ? p.radius : radius[a];
                q.xi = ma.x;
                q.yi = ma.y;
                q.ri = ri;
                // Disk a's share of its contact with slot b, added in the order of the calls.
                auto visit = [&](std::uint32_t b) {
                    const float contact = UniformRadius ? ri + ri : ri + radius[b];
                    sum.add(contact_share<Periodic>(ma, {x[b], y[b], vx[b], vy[b]}, contact, wi, inv_mass[b], p, mu));
                    if (a < b || (Stones && inv_mass[b] == 0.0f)) ++contacts;
                };
                auto visit_mask = [&](unsigned mask, std::uint32_t block) {
                    for (; mask != 0; mask &= mask - 1) visit(block + std::uint32_t(__builtin_ctz(mask)));
                };
                const std::int64_t cx = grid.column_of(ma.x);
                bool general = Periodic && (!periodic_fast || cx == 0 || cx == cells_x - 1);
                if (!general) {
                    const std::int64_t lo = Periodic || cx > 0 ? cx - 1 : 0;
                    const std::int64_t hi = Periodic || cx + 2 < cells_x ? cx + 2 : cells_x;
                    const std::uint32_t b0 = below[lo], e0 = below[hi], b1 = own[lo], e1 = own[hi];
                    const std::uint32_t b2 = above[lo], e2 = above[hi];
                    general = (e0 - b0 > 4) | (e1 - b1 > 4) | (e2 - b2 > 4);
                    if (!general) {
                        const unsigned m0 = candidate_mask<UniformRadius, Periodic>(q, b0, e0, a);
                        const unsigned m1 = candidate_mask<UniformRadius, Periodic>(q, b1, e1, a);
                        const unsigned m2 = candidate_mask<UniformRadius, Periodic>(q, b2, e2, a);
                        if ((m0 | m1 | m2) != 0) [[unlikely]] {
                            visit_mask(m0, b0);
                            visit_mask(m1, b1);
                            visit_mask(m2, b2);
                        }
                    }
                }
                if (general) [[unlikely]] {
                    SlotRange ranges[6];
                    const int range_count = grid.neighbour_ranges<Periodic>(cx, cy, ranges);
                    for (int r = 0; r < range_count; ++r) {
                        for (std::uint32_t block = ranges[r].begin; block < ranges[r].end; block += 4)
                            visit_mask(candidate_mask<UniformRadius, Periodic>(q, block, ranges[r].end, a), block);
                    }
                }
            }
            sum.store(out, a);
        }
    }
    return contacts;
}

// The walls of a reflecting box, for the disks [begin, end) of a block whose update has just
// been stored. The wall law (apply_bounds) changes a disk only when it overlaps a wall, and at
// N = 10^6 about one disk in ten thousand does in a step; but its branches keep a loop that
// applies it to every disk scalar. So the update loops below store the update without the
// walls (a loop without branches, which the compiler vectorises), then this pass looks for a
// disk overlapping a wall (the law's own tests, reduced to one flag in a vectorised loop) and
// applies the law, in scalar, to the disks of the block only if there is one. The law then
// sees the same values it saw when it ran inside the update: bitwise the same result.
template <bool Stones>
void reflect_block(ParticleState<float>& s, const PhaseParams& p, std::size_t begin, std::size_t end) {
    float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    unsigned touching = 0;
    for (std::size_t i = begin; i < end; ++i) {
        const float r = radius[i];
        touching |= unsigned(x[i] - r < p.xmin) | unsigned(x[i] + r > p.xmax) | unsigned(y[i] - r < p.ymin) |
                    unsigned(y[i] + r > p.ymax);
    }
    if (touching == 0) return;
    for (std::size_t i = begin; i < end; ++i)
        apply_bounds<Stones, false>(x[i], y[i], vx[i], vy[i], radius[i], inv_mass[i], p);
}

// Disks per block of the update loops with reflecting walls: the block's x, y, vx, vy (4 KiB)
// are still in the first-level cache when reflect_block reads them back.
inline constexpr std::size_t kWallBlock = 256;

// The wall-free parts of the two update loops, for one block. Their pointers are declared
// restrict (no array overlaps another) and the parameters are copied by value: the vectoriser
// must know that no store of the loop changes what it reads, or it keeps the loop scalar.
inline void add_corrections_block(float* __restrict x, float* __restrict y, float* __restrict vx,
                                  float* __restrict vy, const float* __restrict dx, const float* __restrict dy,
                                  const float* __restrict dvx, const float* __restrict dvy, std::size_t begin,
                                  std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
        x[i] += dx[i];
        y[i] += dy[i];
        vx[i] += dvx[i];
        vy[i] += dvy[i];
    }
}

// Corrections, explicit Euler and forces; a stone keeps its corrected values (a select).
template <bool Gravity, bool Damping, bool Stones>
void correct_and_integrate_block(float* __restrict x, float* __restrict y, float* __restrict vx, float* __restrict vy,
                                 const float* __restrict dx, const float* __restrict dy, const float* __restrict dvx,
                                 const float* __restrict dvy, const float* __restrict inv_mass, const PhaseParams p,
                                 float dt, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
        const float xi = x[i] + dx[i], yi = y[i] + dy[i], vxi = vx[i] + dvx[i], vyi = vy[i] + dvy[i];
        float xm = xi + vxi * dt, ym = yi + vyi * dt, vxm = vxi, vym = vyi;
        kick<Gravity, Damping, false>(vxm, vym, 1.0f, p, dt);
        const bool moving = !Stones || inv_mass[i] != 0.0f;  // stones are kinematic
        x[i] = moving ? xm : xi;
        y[i] = moving ? ym : yi;
        vx[i] = moving ? vxm : vxi;
        vy[i] = moving ? vym : vyi;
    }
}

// Integrate-first, phase 6: apply the corrections, then the world bounds.
// Periodic walls: the loop works on local copies and stores every value back unconditionally,
// so the wrap's branches become selects. Reflecting walls: the corrections in a vectorised
// loop, then reflect_block.
template <bool Stones, bool Periodic>
std::int64_t correct_range(ParticleState<float>& s, Corrections c, const PhaseParams& p, std::size_t begin,
                           std::size_t end) {
    float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    if constexpr (!Periodic) {
        for (std::size_t block = begin; block < end; block += kWallBlock) {
            const std::size_t block_end = std::min(end, block + kWallBlock);
            add_corrections_block(x, y, vx, vy, c.dx, c.dy, c.dvx, c.dvy, block, block_end);
            reflect_block<Stones>(s, p, block, block_end);
        }
        return 0;
    }
    for (std::size_t i = begin; i < end; ++i) {
        float xi = x[i] + c.dx[i], yi = y[i] + c.dy[i], vxi = vx[i] + c.dvx[i], vyi = vy[i] + c.dvy[i];
        apply_bounds<Stones, Periodic>(xi, yi, vxi, vyi, radius[i], inv_mass[i], p);
        x[i] = xi;
        y[i] = yi;
        vx[i] = vxi;
        vy[i] = vyi;
    }
    return 0;
}

// Collide-first, after the contact pass: apply the corrections, explicit Euler (position with
// the velocity before this step's forces, then the forces), then the world bounds; the same
// order of operations as StepSolver::step_collide_first, fused into one pass over memory.
// Reflecting walls: the update of a block in a vectorised loop (a stone keeps its corrected
// values, chosen by a select), then reflect_block.
template <bool Gravity, bool Damping, bool Stones, bool Periodic>
std::int64_t correct_and_integrate_range(ParticleState<float>& s, Corrections c, const PhaseParams& p, float dt,
                                         std::size_t begin, std::size_t end) {
    float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    if constexpr (!Periodic) {
        for (std::size_t block = begin; block < end; block += kWallBlock) {
            const std::size_t block_end = std::min(end, block + kWallBlock);
            correct_and_integrate_block<Gravity, Damping, Stones>(x, y, vx, vy, c.dx, c.dy, c.dvx, c.dvy, inv_mass, p,
                                                                  dt, block, block_end);
            reflect_block<Stones>(s, p, block, block_end);
        }
        return 0;
    }
    for (std::size_t i = begin; i < end; ++i) {
        float xi = x[i] + c.dx[i], yi = y[i] + c.dy[i], vxi = vx[i] + c.dvx[i], vyi = vy[i] + c.dvy[i];
        if (!Stones || inv_mass[i] != 0.0f) {  // stones are kinematic
            xi += vxi * dt;
            yi += vyi * dt;
            kick<Gravity, Damping, false>(vxi, vyi, 1.0f, p, dt);
            apply_bounds<false, Periodic>(xi, yi, vxi, vyi, radius[i], 1.0f, p);
        }
        x[i] = xi;
        y[i] = yi;
        vx[i] = vxi;
        vy[i] = vyi;
    }
    return 0;
}

// One contact's two shares: disk a's and disk b's corrections (dx, dy, dvx, dvy).
struct PairShares {
    float a[4], b[4];
};

// Both shares of each contact a PairList found (pair_list.h), each from the shared contact law
// exactly as the cell path computes it (separation x_self - x_other, relative velocity
// v_self - v_other); a stone's share is zero and not computed. Writes only shares[k], so the
// chunks of a list run in parallel. Returns the contacts, counted as the cell path counts them
// (pairs of two stones not at all).
template <bool Friction, bool Stones, bool UniformRadius, bool Periodic>
std::int64_t pair_shares(const ParticleState<float>& s, const PhaseParams& p, const DiskPair* contacts,
                         std::size_t count, PairShares* shares) {
    const float *x = s.x.data(), *y = s.y.data(), *vx = s.vx.data(), *vy = s.vy.data();
    const float *radius = s.radius.data(), *inv_mass = s.inv_mass.data();
    const float mu = Friction ? p.friction : 0.0f;
    auto share = [&](std::uint32_t self, std::uint32_t other, float out[4]) {
        const float contact = UniformRadius ? p.radius + p.radius : radius[self] + radius[other];
        const auto d = contact_share<Periodic>({x[self], y[self], vx[self], vy[self]},
                                               {x[other], y[other], vx[other], vy[other]}, contact, inv_mass[self],
                                               inv_mass[other], p, mu);
        out[0] = d.dx, out[1] = d.dy, out[2] = d.dvx, out[3] = d.dvy;
    };
    std::int64_t found = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t a = contacts[k].a, b = contacts[k].b;
        const bool a_moves = !Stones || inv_mass[a] != 0.0f, b_moves = !Stones || inv_mass[b] != 0.0f;
        PairShares& out = shares[k];
        if (a_moves) share(a, b, out.a); else out.a[0] = out.a[1] = out.a[2] = out.a[3] = 0.0f;
        if (b_moves) share(b, a, out.b); else out.b[0] = out.b[1] = out.b[2] = out.b[3] = 0.0f;
        found += a_moves || b_moves;
    }
    return found;
}

// The shares of the disks in [begin, end) added to the corrections, contact by contact in the
// order given (disk a's, then disk b's): the order of every per-disk sum, whatever range a
// thread owns. Each thread adds the shares of its own disks only, so the corrections are
// written by the thread that then reads them (a serial pass on one thread made the other
// core fetch every corrected disk's cache lines, and made two threads slower than one at
// N = 10^4: bench/journal.md). The corrections are zero outside the contacts
// (clear_pair_corrections resets them after the update), so each sum starts from zero, as the
// cell path's does; a stone's zero share leaves its zero correction zero.
inline void add_pair_shares(const DiskPair* contacts, const PairShares* shares, std::size_t count, Corrections out,
                            std::uint32_t begin, std::uint32_t end) {
    for (std::size_t k = 0; k < count; ++k)
        for (const auto& [i, d] : {std::pair{contacts[k].a, shares[k].a}, std::pair{contacts[k].b, shares[k].b}}) {
            if (i - begin >= end - begin) continue;  // not in [begin, end) (unsigned: one test)
            out.dx[i] += d[0];
            out.dy[i] += d[1];
            out.dvx[i] += d[2];
            out.dvy[i] += d[3];
        }
}

// After the update has read them: the corrections of the disks in [begin, end) in contact back
// to zero, so that the next step's sums start from zero again without a pass over every disk.
inline void clear_pair_corrections(const DiskPair* contacts, std::size_t count, Corrections out, std::uint32_t begin,
                                   std::uint32_t end) {
    for (std::size_t k = 0; k < count; ++k)
        for (const std::uint32_t i : {contacts[k].a, contacts[k].b})
            if (i - begin < end - begin) out.dx[i] = out.dy[i] = out.dvx[i] = out.dvy[i] = 0.0f;
}

}  // namespace collide::cpu
