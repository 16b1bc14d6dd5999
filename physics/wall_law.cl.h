/* Walls of the world box, for the stepping rules. Written in the common subset of C++ and
 * OpenCL C like contact_law.cl.h (the includer defines `Real`), so step, cpu and the kernels
 * treat walls identically.
 *
 * Reflecting wall, with restitution: a disk whose edge is past
 * the wall is clamped back to touch it (centre at wall + r) and its velocity component into
 * the wall is reversed and scaled by the wall restitution. Clamping keeps wall penetration
 * from accumulating over steps; the energy it removes or adds is part of the rule's error.
 * Periodic wall: the centre is wrapped back into [lo, lo + length).
 */
#ifndef COLLIDE_WALL_LAW_H
#define COLLIDE_WALL_LAW_H

#ifndef COLLIDE_FN
#ifdef __OPENCL_VERSION__
#define COLLIDE_FN static inline
#else
#define COLLIDE_FN inline
#endif
#endif

/* One axis of a reflecting box. `pos` and `vel` are updated in place; returns 1 on contact. */
COLLIDE_FN int reflect_axis(Real* pos, Real* vel, Real radius, Real lo, Real hi, Real wall_e)
{
    if (*pos - radius < lo) {
        *pos = lo + radius;
        if (*vel < (Real)0) *vel = -wall_e * *vel;
        return 1;
    }
    if (*pos + radius > hi) {
        *pos = hi - radius;
        if (*vel > (Real)0) *vel = -wall_e * *vel;
        return 1;
    }
    return 0;
}

/* Periodic axis: the image of `pos` in [lo, lo + length). */
COLLIDE_FN Real wrap_periodic(Real pos, Real lo, Real length)
{
    Real r = pos - lo;
    r -= length * floor(r / length);
    /* floor can leave r == length by rounding when r is a tiny negative number */
    if (r >= length) r -= length;
    return lo + r;
}

/* Minimum-image convention: the separation d along a periodic axis of the given length,
 * brought into [-length/2, length/2]. */
COLLIDE_FN Real minimum_image(Real d, Real length)
{
    return d - length * rint(d / length);
}

#endif /* COLLIDE_WALL_LAW_H */
