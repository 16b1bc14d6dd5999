/* The memory layout shared by the host code and the OpenCL kernels of the `opencl` backend.
 *
 * Written in the common subset of C++ and OpenCL C, like physics/contact_law.cl.h: the includer
 * defines `Real` (float or double) first. The host includes it through particle_layout.h
 * (one namespace per Real, with static_asserts on the layout); the kernels get the same text
 * embedded in front of the kernel files (opencl/kernels/), and the solver checks at load time that the
 * kernel compiler agrees on every size (kernel `layout_probe`).
 *
 * Particle is eight scalars, 32 bytes in float (64 in double),
 * aligned to its own size so that one particle is one aligned memory transaction and
 * neighbouring work-items read neighbouring particles (coalesced access on a GPU). Every
 * member is a Real, so neither compiler has any reason to insert padding of its own; the
 * two slots that would otherwise be padding carry the inverse mass (0 for a kinematic stone) and the mass.
 */
#ifndef COLLIDE_PARTICLE_LAYOUT_H
#define COLLIDE_PARTICLE_LAYOUT_H

typedef struct __attribute__((aligned(8 * sizeof(Real)))) {
    Real x, y;       /* centre position */
    Real vx, vy;     /* velocity */
    Real inv_mass;   /* 1/m, exactly 0 for a stone */
    Real radius;
    Real mass;       /* as given in the scene; only read back, never used by the rules */
    Real unused;     /* pads the struct to 8 Reals */
} Particle;

/* The numbers of one scene that the kernels need, passed by value as one kernel argument.
 * Reals first, then ints, so that the layout has no interior padding on any compiler. */
typedef struct {
    Real h;                       /* step length dt, or the sub-step dt/substeps */
    Real restitution;             /* pair restitution e */
    Real friction;                /* Coulomb coefficient mu */
    Real wall_restitution;
    Real gravity_x, gravity_y;
    Real damping;                 /* gamma in dv/dt = -gamma v */
    Real xmin, ymin, xmax, ymax;  /* the world box */
    Real inv_cell_w, inv_cell_h;  /* cells per unit length, as UniformGrid computes them */
    Real contact_distance;        /* 2r when every disk has the same radius r */
    int cells_x, cells_y;
    int ox_lo, ox_hi, oy_lo, oy_hi; /* neighbour cell offsets, as UniformGrid::axis_offsets */
    int n;                        /* number of particles */
    int unused;
} StepParams;

#endif /* COLLIDE_PARTICLE_LAYOUT_H */
