#include "hard_disk_input.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/numerics/disk_overlap.h"
#include "core/numerics/number_text.h"
#include "core/numerics/representability.h"
#include "core/uniform_grid.h"
#include "physics/stepping_laws.h"

namespace collide {
std::optional<std::string> outside_event_model(const SceneFeatures& f) {
    if (f.friction) return "friction: hard disks of the event-driven model are smooth (no tangential impulse)";
    if (f.damping) return "damping: a velocity-dependent drag is not free flight between events";
    if (f.gravity && f.stones)
        return "gravity with stones: a falling disk moves on a parabola relative to a fixed stone, so their "
               "collision time is a quartic root, which this solver does not compute";
    return std::nullopt;
}

// An event-driven run jumps from collision to collision, so its cost grows with the number of
// events, not with the duration: disks at 1e30 length/time cross the box ~1e30 times and the
// run would never end. The wall (or periodic image) crossings sum_i |v_i| duration / box size
// are a lower bound on the events; beyond this limit the run is refused rather than started.
static constexpr double max_event_estimate = 1e12;

void reject_endless_run(const std::string& who, const Scene& scene, const ParticleState<double>& s) {
    const double box = std::min(scene.world.width(), scene.world.height());
    double crossings = 0;
    for (std::size_t i = 0; i < s.size(); ++i) crossings += std::hypot(s.vx[i], s.vy[i]) * scene.run.duration / box;
    if (crossings > max_event_estimate)
        throw std::runtime_error(who + ": scene '" + scene.name + "': the disks would cross the box about " +
                                 round_trip_text(crossings) + " times in duration " + round_trip_text(scene.run.duration) +
                                 ", each crossing at least one event; more than " + round_trip_text(max_event_estimate) +
                                 " events cannot finish (speeds too large for the box, or the duration too long)");
}

void check_hard_disk_input(const std::string& who, const Scene& scene, const ParticleState<double>& s) {
    const Physics& p = scene.physics;
    if (!(p.restitution >= 0 && p.restitution <= 1))
        throw std::runtime_error(who + ": scene '" + scene.name + "': restitution e = " + round_trip_text(p.restitution) +
                                 " must lie in [0, 1] (e > 1 would create energy at every collision)");
    if (!(p.wall_restitution >= 0 && p.wall_restitution <= 1))
        throw std::runtime_error(who + ": scene '" + scene.name + "': wall restitution " +
                                 round_trip_text(p.wall_restitution) + " must lie in [0, 1]");
    const World& w = scene.world;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::string particle = who + ": particle " + std::to_string(i) + " ";
        if (!(s.radius[i] > 0) || !std::isfinite(s.radius[i]))
            throw std::runtime_error(particle + "has radius " + round_trip_text(s.radius[i]) + "; hard disks need a radius > 0");
        if (!(s.mass[i] > 0) || !std::isfinite(s.mass[i]))
            throw std::runtime_error(particle + "has mass " + round_trip_text(s.mass[i]) + "; expected a mass > 0");
        for (double v : {s.x[i], s.y[i], s.vx[i], s.vy[i]})
            if (!std::isfinite(v)) throw std::runtime_error(particle + "has a non-finite position or velocity");
        if (scene.periodic()) continue;
        const double r = s.radius[i], slack = hard_disk_overlap_tolerance * 2 * r;
        if (s.x[i] - r < w.xmin - slack || s.x[i] + r > w.xmax + slack || s.y[i] - r < w.ymin - slack ||
            s.y[i] + r > w.ymax + slack)
            throw std::runtime_error(particle + "at (" + round_trip_text(s.x[i]) + ", " + round_trip_text(s.y[i]) + ") with radius " +
                                     round_trip_text(r) + " reaches outside the walls [" + round_trip_text(w.xmin) + ", " +
                                     round_trip_text(w.xmax) + "] x [" + round_trip_text(w.ymin) + ", " + round_trip_text(w.ymax) + "]");
    }
    // Then the numbers: masses, speeds, the collision denominator in double (a speed that does
    // not fit is named as such before the run is called endless).
    require_representable(scene, s, Precision::double_, Method::event_driven, who);
    reject_endless_run(who, scene, s);
}

void reject_overlapping_disks(const std::string& who, const Scene& scene, const ParticleState<double>& s) {
    const std::size_t n = s.size();
    if (n < 2) return;
    double r_max = 0;
    for (double r : s.radius) r_max = std::max(r_max, r);
    UniformGrid<double> grid;  // cells of 2 r_max: every possible contact lies in the 3x3 around a disk
    grid.configure(scene.world, 2 * r_max);
    grid.build(s.x.data(), s.y.data(), n);
    const World& w = scene.world;
    for (std::uint32_t i = 0; i < n; ++i) {
        grid.for_each_candidate(s.x[i], s.y[i], [&](std::uint32_t j) {
            if (j <= i) return;
            double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j];
            if (scene.periodic()) {
                dx = WallLaw<double>::minimum_image(dx, w.width());
                dy = WallLaw<double>::minimum_image(dy, w.height());
            }
            const double sigma = s.radius[i] + s.radius[j];
            // The one overlap test of every backend, which cannot underflow (core/numerics/disk_overlap.h).
            if (!centres_closer_than(dx, dy, sigma * (1 - hard_disk_overlap_tolerance))) return;
            const double distance = std::hypot(dx, dy);
            throw std::runtime_error(who + ": initial state overlaps: particles " + std::to_string(i) + " and " +
                                     std::to_string(j) + " overlap by " + round_trip_text(sigma - distance) +
                                     " (centre distance " + round_trip_text(distance) + ", contact distance " +
                                     round_trip_text(sigma) + ")");
        });
    }
}

}  // namespace collide
