/* First piece of every `opencl` program. The host concatenates, in this order:
 *   prelude.cl, physics/contact_law.cl.h, physics/wall_law.cl.h, opencl/particle_layout.cl.h,
 *   layout_probe.cl, grid.cl, reorder.cl, step.cl, group_steps.cl
 * (the headers are the very files the C++ backends compile, embedded at build time), and
 * builds the result with -D flags for the scene's features:
 *   COLLIDE_REAL_DOUBLE      Real = double (needs cl_khr_fp64), else Real = float
 *   COLLIDE_INTEGRATE_FIRST  the integrate-first rule, else collide-first (docs/stepping-rules.md)
 *   COLLIDE_PERIODIC         periodic walls (minimum image, wrapped cells), else reflecting
 *   COLLIDE_GRAVITY, COLLIDE_DAMPING, COLLIDE_FRICTION, COLLIDE_STONES
 *   COLLIDE_UNIFORM_RADIUS   every disk has radius r: contact distance 2r is a constant
 */
#ifdef COLLIDE_REAL_DOUBLE
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double Real;
#else
typedef float Real;
#endif

/* OpenCL C contracts a*b + c into one fused multiply-add by default; C++ (ISO mode) does
 * not. Contraction changes the rounding, so it is switched off: the kernels then round
 * exactly as `step` does, and the double build can match it to the last bits. */
#pragma OPENCL FP_CONTRACT OFF
