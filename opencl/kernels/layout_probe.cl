/* Writes the kernel compiler's view of the shared layout, so that the host can check it
 * against its own (a mismatch would silently scramble every particle). One work-item. */
__kernel void layout_probe(__global int* out)
{
    out[0] = (int)sizeof(Particle);
    out[1] = (int)__alignof__(Particle);
    out[2] = (int)sizeof(StepParams);
    out[3] = (int)sizeof(Real);
}
