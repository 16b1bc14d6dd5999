/* The per-pair contact law of the stepping rules, written once for every backend.
 *
 * This file is written in the common subset of C++ and OpenCL C so that the same text is
 * compiled into `step` (double), `cpu` (float) and the `opencl` kernels. The includer
 * defines the scalar type `Real` before including it (C++: see stepping_laws.h, which
 * wraps it in one namespace per type; OpenCL: a typedef at the top of the kernel source).
 *
 * Physics (docs/stepping-rules.md derives it). Disk i meets disk j; d = x_i - x_j is the
 * line of centres, u = v_i - v_j the relative velocity, w = 1/m the inverse masses (0 for a
 * kinematic stone). With n = d/|d| and the normal relative speed u_n = u.n, conservation of
 * momentum and Newton's restitution law u_n' = -e u_n give the normal impulse
 *     J = -(1 + e) u_n / (w_i + w_j),      v_i' = v_i + w_i J n,      v_j' = v_j - w_j J n.
 * For e = 1 and w = 1/m this is the textbook elastic formula
 *     v_i' = v_i - 2 m_j/(m_i+m_j) (u.d)/|d|^2 d.
 * The impulse is applied only to approaching pairs (u_n < 0): a separating pair that still
 * overlaps must not be pulled back together.
 * Coulomb friction acts on the tangential relative velocity u_t = u - u_n n with an impulse
 * of at most mu J, capped so that it can stop the tangential sliding but never reverse it.
 * Overlapping disks are pushed apart along n by the overlap R - |d|, split by inverse mass
 * (the lighter disk moves further; the centre of mass does not move).
 *
 * The function is one-sided: it returns only disk i's share. Disk j computes the mirror
 * image when it is processed, so a parallel pass writes only its own particle's slots.
 */
#ifndef COLLIDE_CONTACT_LAW_H
#define COLLIDE_CONTACT_LAW_H

#ifdef __OPENCL_VERSION__
#define COLLIDE_FN static inline
#else
#define COLLIDE_FN inline
#endif

/* Disk i's share of one contact: a position correction and a velocity change. */
typedef struct {
    Real dx, dy;    /* position correction of disk i */
    Real dvx, dvy;  /* velocity change of disk i */
} ContactDelta;

/* Inputs: the separation d = (sep_x, sep_y) = x_i - x_j (minimum image for periodic walls),
 * the relative velocity u = v_i - v_j, the contact distance R = r_i + r_j, the inverse masses
 * and the material parameters. Disks that do not overlap (|d| >= R) or whose centres
 * coincide (no defined normal) get a zero delta. */
COLLIDE_FN ContactDelta contact_delta(Real sep_x, Real sep_y, Real rel_vx, Real rel_vy,
                                      Real contact_distance, Real inv_mass_i, Real inv_mass_j,
                                      Real restitution, Real friction)
{
    ContactDelta out;
    out.dx = 0; out.dy = 0; out.dvx = 0; out.dvy = 0;

    const Real dist2 = sep_x * sep_x + sep_y * sep_y;
    const Real w_sum = inv_mass_i + inv_mass_j;
    /* Squared-distance test first: the square root is taken only for real contacts. */
    if (dist2 >= contact_distance * contact_distance || dist2 == (Real)0 || w_sum == (Real)0)
        return out;

    const Real dist = sqrt(dist2);
    const Real nx = sep_x / dist, ny = sep_y / dist;
    const Real share_i = inv_mass_i / w_sum;  /* = m_j / (m_i + m_j) */

    /* Positional correction: disk i moves its inverse-mass share of the overlap. */
    const Real overlap = contact_distance - dist;
    out.dx = share_i * overlap * nx;
    out.dy = share_i * overlap * ny;

    /* Normal impulse, approaching pairs only. */
    const Real un = rel_vx * nx + rel_vy * ny;
    if (un >= (Real)0)
        return out;
    const Real impulse_n = -((Real)1 + restitution) * un / w_sum;
    out.dvx = inv_mass_i * impulse_n * nx;
    out.dvy = inv_mass_i * impulse_n * ny;

    /* Coulomb friction on the tangent: |J_t| <= mu J_n, and no more than what stops the
     * tangential sliding (|u_t| / w_sum), so friction never reverses it. */
    if (friction > (Real)0) {
        const Real tx = rel_vx - un * nx, ty = rel_vy - un * ny;
        const Real ut = sqrt(tx * tx + ty * ty);
        if (ut > (Real)0) {
            const Real stop = ut / w_sum;
            const Real coulomb = friction * impulse_n;
            const Real impulse_t = coulomb < stop ? coulomb : stop;
            out.dvx -= inv_mass_i * impulse_t * tx / ut;
            out.dvy -= inv_mass_i * impulse_t * ty / ut;
        }
    }
    return out;
}

#endif /* COLLIDE_CONTACT_LAW_H */
