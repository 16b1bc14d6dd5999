/* The uniform grid built on the device: the same counting sort as core/uniform_grid.h, and
 * the same result, bit for bit (the tests compare the two).
 *   grid_count      cell of every disk; atomic increment of its cell's count, which also
 *                   gives the disk a rank inside its cell (in no particular order)
 *   scan_blocks     exclusive prefix sum of the counts -> cell_start (blocks scanned by
 *   add_block_offsets  work-groups, the block sums scanned recursively by the host)
 *   grid_scatter    sorted_index[cell_start[c] + rank] = i
 *   grid_sort_cells the atomics made the order inside a cell depend on thread timing;
 *                   sorting each cell's few indices restores increasing index order, so the
 *                   neighbour order, and every sum over neighbours, is deterministic.
 *   grid_sort_cells_by_scene_index  the same once the disks have been moved into cell order
 *                   (reorder.cl): a disk's slot is then no longer its index in the scene, so
 *                   the sort goes by scene index, the order in which `step` visits them.
 */

/* Cell coordinate along one axis, clamped to the border cells (NaN goes to cell 0), exactly
 * as UniformGrid::clamp_cell. */
static inline int clamp_cell(Real scaled, int cells)
{
    if (!(scaled >= (Real)0)) return 0;
    if (scaled >= (Real)cells) return cells - 1;
    return (int)scaled;
}

static inline int cell_x_of(Real x, const StepParams* p) { return clamp_cell((x - p->xmin) * p->inv_cell_w, p->cells_x); }
static inline int cell_y_of(Real y, const StepParams* p) { return clamp_cell((y - p->ymin) * p->inv_cell_h, p->cells_y); }

/* Disk i's cell, and its rank among the disks counted into that cell so far. */
static inline void count_disk(int i, __global const Particle* particles, const StepParams* p,
                              __global uint* cell_of, __global uint* rank, __global volatile uint* counts)
{
    const uint c = (uint)(cell_y_of(particles[i].y, p) * p->cells_x + cell_x_of(particles[i].x, p));
    cell_of[i] = c;
    rank[i] = atomic_inc(&counts[c]);
}

__kernel void grid_count(__global const Particle* particles, const StepParams params,
                         __global uint* cell_of, __global uint* rank, __global volatile uint* counts)
{
    const int i = get_global_id(0);
    if (i >= params.n) return;
    count_disk(i, particles, &params, cell_of, rank, counts);
}

/* Exclusive scan, in place, of the values [begin, end) each work-item of the group owns (the
 * items' ranges consecutive, in item order). Each item sums its values serially, the
 * work-group scans the per-item sums in local memory (Hillis and Steele's doubling scan), and
 * each item then rewrites its values as running sums from its offset. The serial part keeps
 * the work linear in the values; the doubling scan (log2 of the group size steps) runs on the
 * group's sums only. Integer sums, so the order of additions does not matter. Returns the
 * group's total. Every item of the group must call it (it holds barriers). */
static inline uint scan_group_ranges(__global uint* values, uint begin, uint end, __local uint* scratch)
{
    const uint lid = get_local_id(0), size = get_local_size(0);
    uint own = 0;
    for (uint k = begin; k < end; ++k) own += values[k];
    scratch[lid] = own;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint offset = 1; offset < size; offset *= 2) {
        const uint add = lid >= offset ? scratch[lid - offset] : 0u;
        barrier(CLK_LOCAL_MEM_FENCE);
        scratch[lid] += add;
        barrier(CLK_LOCAL_MEM_FENCE);
    }
    uint running = scratch[lid] - own;  /* inclusive -> exclusive: this item's offset */
    for (uint k = begin; k < end; ++k) {
        const uint value = values[k];
        values[k] = running;
        running += value;
    }
    const uint total = scratch[size - 1];
    barrier(CLK_LOCAL_MEM_FENCE);  /* scratch may be reused at once */
    return total;
}

/* Exclusive scan of one block of get_local_size(0) * chunk values, `chunk` consecutive
 * values per work-item; block_sums[g] receives the block's total for the next level of the
 * scan. */
__kernel void scan_blocks(__global uint* values, const uint count, const uint chunk, __global uint* block_sums,
                          __local uint* scratch)
{
    const uint begin = (uint)get_global_id(0) * chunk;
    const uint total = scan_group_ranges(values, begin, min(begin + chunk, count), scratch);
    if (get_local_id(0) == 0) block_sums[get_group_id(0)] = total;
}

/* values[k] += the scanned total of all blocks before k's block. */
__kernel void add_block_offsets(__global uint* values, const uint count, const uint block_values,
                                __global const uint* block_offsets)
{
    const uint k = get_global_id(0);
    if (k < count) values[k] += block_offsets[k / block_values];
}

__kernel void grid_scatter(__global const uint* cell_of, __global const uint* rank,
                           __global const uint* cell_start, __global uint* sorted_index, const int n)
{
    const int i = get_global_id(0);
    if (i >= n) return;
    sorted_index[cell_start[cell_of[i]] + rank[i]] = (uint)i;
}

/* The key a cell's disks are sorted by: the disk's index in the scene. While the disks sit in
 * the scene's order (scene_index == 0) that is the slot itself; after a reorder by cell it is
 * scene_index[slot]. */
static inline uint scene_index_of(uint slot, __global const uint* scene_index)
{
    return scene_index ? scene_index[slot] : slot;
}

/* Insertion sort of one cell's slots by scene index (a cell holds a handful of disks). */
static inline void sort_cell(__global uint* sorted_index, uint begin, uint end, __global const uint* scene_index)
{
    for (uint k = begin + 1; k < end; ++k) {
        const uint slot = sorted_index[k];
        const uint key = scene_index_of(slot, scene_index);
        uint m = k;
        while (m > begin && scene_index_of(sorted_index[m - 1], scene_index) > key) {
            sorted_index[m] = sorted_index[m - 1];
            --m;
        }
        sorted_index[m] = slot;
    }
}

/* Disks still in the scene's order: slot = scene index. */
__kernel void grid_sort_cells(__global const uint* cell_start, __global uint* sorted_index, const int cell_count)
{
    const int c = get_global_id(0);
    if (c >= cell_count) return;
    sort_cell(sorted_index, cell_start[c], cell_start[c + 1], 0);
}

/* Disks moved into cell order: slot k holds scene disk scene_index[k]. */
__kernel void grid_sort_cells_by_scene_index(__global const uint* cell_start, __global uint* sorted_index,
                                             __global const uint* scene_index, const int cell_count)
{
    const int c = get_global_id(0);
    if (c >= cell_count) return;
    sort_cell(sorted_index, cell_start[c], cell_start[c + 1], scene_index);
}
