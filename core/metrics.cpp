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

// Calls on_overlap(relative_depth) once for every overlapping pair i < j of finite disks.
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
                on_overlap(std::max(0.0, (contact - std::hypot(dx, dy)) / contact));
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
    CompensatedSum depth_sum;
    for_each_overlap(scene, s, [&](double depth) {
        ++m.overlapping_pairs;
        m.max_overlap = std::max(m.max_overlap, depth);
        depth_sum.add(depth);
    });
    if (m.overlapping_pairs > 0) m.mean_overlap = depth_sum.value() / double(m.overlapping_pairs);
    return m;
}

std::vector<double> overlap_depths(const Scene& scene, const ParticleState<double>& state) {
    std::vector<double> depths;
    for_each_overlap(scene, state, [&](double depth) { depths.push_back(depth); });
    return depths;
}

}  // namespace collide
