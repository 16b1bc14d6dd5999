/* Many steps in one launch, for a scene one work-group runs on its own (option grid = "group").
 *
 * A launch of the per-disk kernels costs tens of microseconds of driver work (PoCL: command
 * creation, scheduling, a queue round trip), which is all of a step's cost for a few disks.
 * Work-items of one work-group can synchronise with barrier(), so a single group can run the
 * whole step sequence in a loop: the host launches once per output interval instead of four
 * to seven times per step. Each pass is the same work as the per-disk kernels, from the same
 * functions:
 *
 *   integrate-first only: integrate_disk        (step.cl)
 *   the grid:             count_disk, scan_group_ranges, scatter, sort_cell   (grid.cl)
 *   the contact pass:     resolve_disk           (step.cl), from `in` into `out`, then swap
 *
 * The grid is the device grid's, cells sorted by scene index, so every disk meets its
 * neighbours in the order of `step` and `cpu` and every sum rounds as theirs do. The disks stay
 * in the scene's order (no reorder: a group's disks are few enough to stay in cache), so a
 * slot is its disk's scene index.
 *
 * Work-item k of the group handles disks (and cells) k, k + L, k + 2L, ... (L = the group's
 * size), so the kernel is correct for any N; it is chosen where one compute unit is fast
 * enough (opencl_solver.cpp, default_grid_mode). A pass's phases are separated by barriers
 * with a global fence: within one work-group that makes every item's writes to global memory
 * visible to the others.
 *
 * `passes`: steps of the collide-first rule, or sub-steps of the integrate-first rule (the
 * schedule of physics/step_schedule.h: a step is `substeps` such passes). The result is in
 * `b` after an odd number of passes, in `a` after an even one.
 */

#define FOR_EACH_ITEM_OF_GROUP(k, count) \
    for (uint k = get_local_id(0); k < (uint)(count); k += get_local_size(0))

#define GROUP_BARRIER() barrier(CLK_GLOBAL_MEM_FENCE | CLK_LOCAL_MEM_FENCE)

/* The grid of the disks in `in` (in the scene's order), as the device grid builds it. */
static inline void build_grid_in_group(__global const Particle* in, const StepParams* p,
                                       __global uint* cell_start, __global uint* sorted_index,
                                       __global uint* cell_of, __global uint* rank, __local uint* scratch)
{
    const uint cells = (uint)(p->cells_x * p->cells_y);
    FOR_EACH_ITEM_OF_GROUP(c, cells + 1) cell_start[c] = 0;
    GROUP_BARRIER();
    FOR_EACH_ITEM_OF_GROUP(i, p->n) count_disk((int)i, in, p, cell_of, rank, cell_start);
    GROUP_BARRIER();
    const uint chunk = (cells + 1 + get_local_size(0) - 1) / get_local_size(0);
    const uint begin = get_local_id(0) * chunk;
    scan_group_ranges(cell_start, min(begin, cells + 1), min(begin + chunk, cells + 1), scratch);
    GROUP_BARRIER();
    FOR_EACH_ITEM_OF_GROUP(i, p->n) sorted_index[cell_start[cell_of[i]] + rank[i]] = i;
    GROUP_BARRIER();
    FOR_EACH_ITEM_OF_GROUP(c, cells) sort_cell(sorted_index, cell_start[c], cell_start[c + 1], 0);
    GROUP_BARRIER();
}

__kernel void run_steps_in_group(__global Particle* a, __global Particle* b, __global uint* cell_start,
                                 __global uint* sorted_index, __global uint* cell_of, __global uint* rank,
                                 __global uint* contact_count, const StepParams params, const int passes,
                                 __local uint* scratch)
{
    __global Particle* in = a;
    __global Particle* out = b;
    for (int pass = 0; pass < passes; ++pass) {
#ifdef COLLIDE_INTEGRATE_FIRST
        FOR_EACH_ITEM_OF_GROUP(i, params.n) integrate_disk((int)i, in, &params);
        GROUP_BARRIER();
#endif
        build_grid_in_group(in, &params, cell_start, sorted_index, cell_of, rank, scratch);
        FOR_EACH_ITEM_OF_GROUP(i, params.n) resolve_disk((int)i, in, out, cell_start, sorted_index, contact_count, &params);
        GROUP_BARRIER();
        __global Particle* const previous = in;
        in = out;
        out = previous;
    }
}
