/* Moves the disks into cell order, the order of the grid's slots. The particles never leave
 * their slots otherwise, so with a scene listed in random order (as any random generator
 * lists it) the neighbours a contact pass reads lie scattered over the whole buffer; in cell
 * order the disks of one cell, and of the cells beside it in a row, are neighbours in memory.
 *
 *   gather_cell_order  out[k] = in[sorted_index[k]] (the particle and its scene index), then
 *                      sorted_index[k] = k: slot k now holds the disk the grid put there, so
 *                      cell_start is unchanged and the grid describes the moved disks.
 *
 * The per-disk contact counts stay where they are: only their total is ever read.
 */
__kernel void gather_cell_order(__global const Particle* in, __global Particle* out,
                                __global const uint* scene_index_in, __global uint* scene_index_out,
                                __global uint* sorted_index, const int n)
{
    const int k = get_global_id(0);
    if (k >= n) return;
    const uint from = sorted_index[k];
    out[k] = in[from];
    scene_index_out[k] = scene_index_in[from];
    sorted_index[k] = (uint)k;  /* read and written by this work-item only */
}
