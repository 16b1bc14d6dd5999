/* The stepping rules (docs/stepping-rules.md) as kernels, one work-item per disk. Each
 * kernel performs, for its disk, the operations of reference/step_solver.cpp in the same
 * order, so the double build reproduces `step` to rounding of the sums' order. The kernels
 * carry the phase names of core/phase_timer.h:
 *
 *   collide-first, one step:      [grid]  collide_and_correct
 *   integrate-first, one sub-step:  integrate  [grid]  collide_and_correct
 *
 * collide_and_correct reads a snapshot (`in`) and writes the new state to another buffer
 * (`out`), so every disk sees its neighbours as they were at the start of the pass (the
 * Jacobi update of the rules) and no work-item can see another's write. It applies the
 * summed contact deltas, then finishes the disk's step: explicit Euler and walls
 * (collide-first) or walls alone (integrate-first). With two buffers, integration needs no
 * kernel of its own in the collide-first rule: no disk reads a position another has moved.
 */

/* Field acceleration minus linear drag, a = g - gamma v; a term the scene does not use is
 * a literal zero, which the compiler removes. */
#ifdef COLLIDE_GRAVITY
#define FIELD_X(p) ((p)->gravity_x)
#define FIELD_Y(p) ((p)->gravity_y)
#else
#define FIELD_X(p) ((Real)0)
#define FIELD_Y(p) ((Real)0)
#endif
#ifdef COLLIDE_DAMPING
#define DRAG(p, v) ((p)->damping * (v))
#else
#define DRAG(p, v) ((Real)0)
#endif

#ifdef COLLIDE_STONES
#define IS_STONE(particle) ((particle).inv_mass == (Real)0)
#else
#define IS_STONE(particle) 0
#endif

/* v += (g - gamma v) h, as StepSolver::integrate_velocities. */
static inline void integrate_velocity(Particle* q, const StepParams* p)
{
#if defined(COLLIDE_GRAVITY) || defined(COLLIDE_DAMPING)
    q->vx += (FIELD_X(p) - DRAG(p, q->vx)) * p->h;
    q->vy += (FIELD_Y(p) - DRAG(p, q->vy)) * p->h;
#endif
}

/* x += v h, as StepSolver::integrate_positions. */
static inline void integrate_position(Particle* q, const StepParams* p)
{
    q->x += q->vx * p->h;
    q->y += q->vy * p->h;
}

static inline void apply_walls(Particle* q, const StepParams* p)
{
#ifdef COLLIDE_PERIODIC
    q->x = wrap_periodic(q->x, p->xmin, p->xmax - p->xmin);
    q->y = wrap_periodic(q->y, p->ymin, p->ymax - p->ymin);
#else
    reflect_axis(&q->x, &q->vx, q->radius, p->xmin, p->xmax, p->wall_restitution);
    reflect_axis(&q->y, &q->vy, q->radius, p->ymin, p->ymax, p->wall_restitution);
#endif
}

/* A neighbour cell coordinate, wrapped on periodic axes; -1 if it lies outside the box. */
static inline int neighbour_cell(int c, int cells)
{
    if (c >= 0 && c < cells) return c;
#ifdef COLLIDE_PERIODIC
    return (c + cells) % cells;
#else
    return -1;
#endif
}

/* Adds disk i's contacts with the disks in slots [begin, end) of sorted_index to `sum`.
 * Counts each pair once, as `step` does: by the lower slot, or by the moving disk when the
 * other is a stone (a stone never runs this loop). The total does not depend on which slot
 * holds which disk. */
static inline void add_contacts(int i, const Particle* pi, __global const Particle* in,
                                __global const uint* sorted_index, uint begin, uint end,
                                const StepParams* p, ContactDelta* sum, uint* contacts)
{
#ifdef COLLIDE_FRICTION
    const Real friction = p->friction;
#else
    const Real friction = 0;
#endif
    for (uint k = begin; k < end; ++k) {
        const int j = (int)sorted_index[k];
        if (j == i) continue;
        const Particle pj = in[j];
        Real sep_x = pi->x - pj.x, sep_y = pi->y - pj.y;
#ifdef COLLIDE_PERIODIC
        sep_x = minimum_image(sep_x, p->xmax - p->xmin);
        sep_y = minimum_image(sep_y, p->ymax - p->ymin);
#endif
#ifdef COLLIDE_UNIFORM_RADIUS
        const Real contact = p->contact_distance;
#else
        const Real contact = pi->radius + pj.radius;
#endif
        /* Squared distances: no square root for the pairs that do not touch (most of them). */
        if (sep_x * sep_x + sep_y * sep_y >= contact * contact) continue;
        const ContactDelta d = contact_delta(sep_x, sep_y, pi->vx - pj.vx, pi->vy - pj.vy, contact,
                                             pi->inv_mass, pj.inv_mass, p->restitution, friction);
        sum->dx += d.dx;
        sum->dy += d.dy;
        sum->dvx += d.dvx;
        sum->dvy += d.dvy;
        if (i < j || IS_STONE(pj)) ++*contacts;
    }
}

/* Disk i's summed contact deltas over the 3x3 cell neighbourhood, neighbours visited in the
 * order of UniformGrid::for_each_candidate (rows, then columns, then increasing index).
 * Neighbouring cells of one row are neighbours in sorted_index too, so a row whose cells
 * need no periodic wrap is one contiguous slot range: the same disks in the same order,
 * for two reads of cell_start instead of six. */
static inline ContactDelta sum_contacts(int i, const Particle* pi, __global const Particle* in,
                                        __global const uint* cell_start, __global const uint* sorted_index,
                                        const StepParams* p, uint* contacts)
{
    ContactDelta sum;
    sum.dx = 0; sum.dy = 0; sum.dvx = 0; sum.dvy = 0;
    const int cx = cell_x_of(pi->x, p), cy = cell_y_of(pi->y, p);
    for (int oy = p->oy_lo; oy <= p->oy_hi; ++oy) {
        const int ny = neighbour_cell(cy + oy, p->cells_y);
        if (ny < 0) continue;
        const int row = ny * p->cells_x;
        int x_lo = cx + p->ox_lo, x_hi = cx + p->ox_hi;
#ifdef COLLIDE_PERIODIC
        if (x_lo < 0 || x_hi >= p->cells_x) {  /* wrapped cells are not contiguous: one by one */
            for (int ox = p->ox_lo; ox <= p->ox_hi; ++ox) {
                const int c = row + neighbour_cell(cx + ox, p->cells_x);
                add_contacts(i, pi, in, sorted_index, cell_start[c], cell_start[c + 1], p, &sum, contacts);
            }
            continue;
        }
#else
        x_lo = max(x_lo, 0);  /* a reflecting box has no cells beyond its walls */
        x_hi = min(x_hi, p->cells_x - 1);
#endif
        add_contacts(i, pi, in, sorted_index, cell_start[row + x_lo], cell_start[row + x_hi + 1], p, &sum, contacts);
    }
    return sum;
}

/* Integrate-first only: velocity, then position with the new velocity (semi-implicit Euler). */
static inline void integrate_disk(int i, __global Particle* particles, const StepParams* p)
{
    Particle q = particles[i];
    if (IS_STONE(q)) return;  /* kinematic: never integrated */
    integrate_velocity(&q, p);
    integrate_position(&q, p);
    particles[i] = q;
}

/* Disk i's contact pass from the snapshot `in` into `out`, and the rest of its step. */
static inline void resolve_disk(int i, __global const Particle* in, __global Particle* out,
                                __global const uint* cell_start, __global const uint* sorted_index,
                                __global uint* contact_count, const StepParams* p)
{
    Particle q = in[i];
    if (IS_STONE(q)) {  /* a stone's share of every contact is zero, and it never moves */
        out[i] = q;
        return;
    }
    uint contacts = 0;
    const ContactDelta d = sum_contacts(i, &q, in, cell_start, sorted_index, p, &contacts);
    q.x += d.dx;
    q.y += d.dy;
    q.vx += d.dvx;
    q.vy += d.dvy;
#ifndef COLLIDE_INTEGRATE_FIRST
    /* Explicit Euler with the post-contact velocity, then this step's forces. */
    integrate_position(&q, p);
    integrate_velocity(&q, p);
#endif
    apply_walls(&q, p);
    out[i] = q;
    contact_count[i] += contacts;
}

__kernel void integrate(__global Particle* particles, const StepParams params)
{
    const int i = get_global_id(0);
    if (i < params.n) integrate_disk(i, particles, &params);
}

__kernel void collide_and_correct(__global const Particle* in, __global Particle* out,
                                 __global const uint* cell_start, __global const uint* sorted_index,
                                 __global uint* contact_count, const StepParams params)
{
    const int i = get_global_id(0);
    if (i < params.n) resolve_disk(i, in, out, cell_start, sorted_index, contact_count, &params);
}
