#include "overlap_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/stepping_laws.h"
#include "parallel_chunks.h"

namespace collide::view {
namespace {

// Brings a coordinate that a wrap took past the box back inside it.
double wrap_into(double v, double lo, double hi) {
    if (v < lo) return v + (hi - lo);
    if (v >= hi) return v - (hi - lo);
    return v;
}

}  // namespace

void OverlapFinder::find(const World& world, const ParticleState<double>& s, std::vector<OverlapMark>& out,
                         int threads) {
    out.clear();
    const std::size_t n = s.size();
    if (n < 2) return;
    world_ = world;
    grid_.configure(world, 2 * *std::max_element(s.radius.begin(), s.radius.end()));
    grid_.build(s.x.data(), s.y.data(), n);
    gather_in_slot_order(s, threads);
    const ChunkPlan plan = plan_chunks(n, threads);
    if (chunks_.size() < plan.count) chunks_.resize(plan.count);
    parallel_chunks(plan, threads, [&](std::size_t c, std::size_t begin, std::size_t end) {
        chunks_[c].clear();
        find_from_slots(begin, end, chunks_[c]);
    });
    for (std::size_t c = 0; c < plan.count; ++c) out.insert(out.end(), chunks_[c].begin(), chunks_[c].end());
}

// x_, y_, radius_ in slot order; a disk with a non-finite coordinate or velocity gets a NaN
// position, which no distance test passes (the metrics skip such disks too).
void OverlapFinder::gather_in_slot_order(const ParticleState<double>& s, int threads) {
    const std::size_t n = s.size();
    x_.resize(n);
    y_.resize(n);
    radius_.resize(n);
    const std::vector<std::uint32_t>& index = grid_.sorted_index();
    parallel_chunks(plan_chunks(n, threads), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const std::size_t i = index[k];
            const bool finite = s.is_finite(i);
            x_[k] = finite ? s.x[i] : std::numeric_limits<double>::quiet_NaN();
            y_[k] = s.y[i];
            radius_[k] = s.radius[i];
        }
    });
}

// The pairs (a, b) with slot a in [begin, end) and slot b > a: each pair once.
void OverlapFinder::find_from_slots(std::size_t begin, std::size_t end, std::vector<OverlapMark>& out) const {
    const bool periodic = world_.boundary == Boundary::periodic;
    const double lx = world_.width(), ly = world_.height();
    const std::vector<std::uint32_t>& index = grid_.sorted_index();  // slot -> disk
    for (std::size_t a = begin; a < end; ++a) {
        const double xa = x_[a], ya = y_[a], ra = radius_[a];
        grid_.for_each_neighbour_range(grid_.cell_x(xa), grid_.cell_y(ya), [&](std::uint32_t first, std::uint32_t last) {
            for (std::size_t b = std::max<std::size_t>(first, a + 1); b < last; ++b) {
                double dx = x_[b] - xa, dy = y_[b] - ya;
                if (periodic) {
                    dx = WallLaw<double>::minimum_image(dx, lx);
                    dy = WallLaw<double>::minimum_image(dy, ly);
                }
                const double contact = ra + radius_[b], d2 = dx * dx + dy * dy;
                if (!(d2 < contact * contact)) continue;
                OverlapMark m{xa + dx / 2, ya + dy / 2, std::min(ra, radius_[b]), (contact - std::sqrt(d2)) / contact,
                              index[a], index[b]};
                if (periodic) {
                    m.x = wrap_into(m.x, world_.xmin, world_.xmax);
                    m.y = wrap_into(m.y, world_.ymin, world_.ymax);
                }
                out.push_back(m);
            }
        });
    }
}

Metrics frame_metrics(const Scene& scene, const ParticleState<double>& state, double time,
                      const std::vector<OverlapMark>& overlaps) {
    Metrics m = compute_disk_metrics(scene, state, time);
    OverlapTally tally(scene, state);
    for (const OverlapMark& o : overlaps) tally.add(o.i, o.j, o.depth);
    tally.write_into(m);
    return m;
}

}  // namespace collide::view
