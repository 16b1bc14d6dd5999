#include "core/metrics.h"

#include <algorithm>
#include <cmath>

#include "core/numerics/compensated_sum.h"
#include "core/numerics/disk_overlap.h"
#include "physics/stepping_laws.h"
#include "core/uniform_grid.h"

namespace collide {
namespace {

double max_radius(const ParticleState<double>& s) {
    double r = 0;
    for (double ri : s.radius) r = std::max(r, ri);
    return r;
}

// One overlapping pair i < j and its relative depth (r_i + r_j - d)/(r_i + r_j).
struct Overlap {
    std::size_t i, j;
    double depth;
};

// Calls on_overlap(Overlap) once for every overlapping pair i < j of finite disks.
template <typename OnOverlap>
void for_each_overlap(const Scene& scene, const ParticleState<double>& s, OnOverlap&& on_overlap) {
    const std::size_t n = s.size();
    if (n < 2) return;
    UniformGrid<double> grid;
    grid.configure(scene.world, 2 * max_radius(s));
    grid.build(s.x.data(), s.y.data(), n);
    const bool periodic = scene.periodic();
    const double lx = scene.world.width(), ly = scene.world.height();
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.is_finite(i)) continue;
        grid.for_each_candidate(s.x[i], s.y[i], [&](std::uint32_t j) {
            if (j <= i || !s.is_finite(j)) return;
            double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j];
            if (periodic) {
                dx = WallLaw<double>::minimum_image(dx, lx);
                dy = WallLaw<double>::minimum_image(dy, ly);
            }
            const double contact = s.radius[i] + s.radius[j];
            if (centres_closer_than(dx, dy, contact))
                on_overlap(Overlap{i, j, std::max(0.0, (contact - std::hypot(dx, dy)) / contact)});
        });
    }
}

// Depth beyond the nearest reflecting wall, relative to the disk's radius (0 if inside).
double wall_penetration(const World& w, double x, double y, double r) {
    const double depth = std::max({w.xmin - (x - r), (x + r) - w.xmax, w.ymin - (y - r),
                                   (y + r) - w.ymax, 0.0});
    return depth / r;
}

}  // namespace

OverlapTally::OverlapTally(const Scene& scene, const ParticleState<double>& state)
    : state_(state), step_(scene.run.dt / double(std::max(1, scene.run.substeps))) {}

// The part of the depth that one step of the pair's relative motion cannot explain: two disks
// moving on straight lines at relative speed |v_i - v_j| press at most |v_i - v_j| h into each
// other in a step h from contact, so a pair deeper than that has stayed overlapped for more
// than one step (a missed or too weak impulse). A stepping rule removes an overlap in the step
// that detects it (collide-first: the positional correction; integrate-first: the projection),
// so at an output only pairs that met in the last step overlap, each by at most its one-step
// approach (docs/validation.md, "overlap_beyond_step").
void OverlapTally::add(std::size_t i, std::size_t j, double depth) {
    ++pairs_;
    max_depth_ = std::max(max_depth_, depth);
    depth_sum_.add(depth);
    const ParticleState<double>& s = state_;
    const double relative_speed = std::hypot(s.vx[i] - s.vx[j], s.vy[i] - s.vy[j]);
    const double one_step = relative_speed * step_ / (s.radius[i] + s.radius[j]);
    max_beyond_step_ = std::max(max_beyond_step_, depth - one_step);
}

void OverlapTally::write_into(Metrics& m) const {
    m.overlapping_pairs = pairs_;
    m.max_overlap = max_depth_;
    m.mean_overlap = pairs_ > 0 ? depth_sum_.value() / double(pairs_) : 0.0;
    m.max_overlap_beyond_step = max_beyond_step_;
}

Metrics compute_disk_metrics(const Scene& scene, const ParticleState<double>& s, double time) {
    Metrics m;
    m.time = time;
    CompensatedSum px, py, kinetic, potential;
    const double gx = scene.physics.gravity_x, gy = scene.physics.gravity_y;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.is_finite(i)) {
            ++m.nonfinite;
            continue;
        }
        if (s.is_stone(i)) continue;  // infinite mass: carries no momentum budget
        const double mass = s.mass[i];
        px.add(mass * s.vx[i]);
        py.add(mass * s.vy[i]);
        kinetic.add(disk_kinetic_energy(mass, s.vx[i], s.vy[i]));
        potential.add(-mass * (gx * s.x[i] + gy * s.y[i]));
        if (!scene.periodic())
            m.max_wall_penetration = std::max(m.max_wall_penetration,
                                              wall_penetration(scene.world, s.x[i], s.y[i], s.radius[i]));
    }
    m.momentum_x = px.value();
    m.momentum_y = py.value();
    m.kinetic_energy = kinetic.value();
    m.potential_energy = potential.value();
    return m;
}

Metrics compute_metrics(const Scene& scene, const ParticleState<double>& s, double time) {
    Metrics m = compute_disk_metrics(scene, s, time);
    OverlapTally tally(scene, s);
    for_each_overlap(scene, s, [&](const Overlap& o) { tally.add(o.i, o.j, o.depth); });
    tally.write_into(m);
    return m;
}

std::vector<double> overlap_depths(const Scene& scene, const ParticleState<double>& state) {
    std::vector<double> depths;
    for_each_overlap(scene, state, [&](const Overlap& o) { depths.push_back(o.depth); });
    return depths;
}

}  // namespace collide
