#include "sampling/sampler_input.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/numerics/number_text.h"
#include "core/scene/scene_features.h"
#include "reference/hard_disk_input.h"

namespace collide {

std::optional<std::string> outside_sampler_model(const SceneFeatures& f, const SamplerLimits& limits) {
    if (f.reflecting_walls && !limits.walls)
        return "reflecting walls: this sampler handles periodic boxes only";
    if (f.gravity) return "gravity: a sampler draws from the uniform measure of hard disks, which has no potential energy";
    if (f.damping) return "damping: a sampler has no velocities to damp";
    if (f.friction) return "friction: a sampler has no collisions to exchange tangential impulse in";
    if (f.restitution != 1)
        return "restitution e = " + round_trip_text(f.restitution) +
               " < 1: inelastic collisions are a claim about dynamics; a sampler samples the equilibrium of elastic hard disks";
    if (f.reflecting_walls && f.wall_restitution != 1)
        return "wall restitution " + round_trip_text(f.wall_restitution) + " < 1: a claim about dynamics, which a sampler has none of";
    return std::nullopt;
}

namespace {

void require_equal_movable_disks(const std::string& who, const ParticleState<double>& s) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::string disk = who + ": particle " + std::to_string(i) + " ";
        if (s.is_stone(i))
            throw std::runtime_error(disk + "is a stone: a sampler moves every disk (stones, moving or not, are not sampled)");
        if (!(s.radius[i] > 0) || !std::isfinite(s.radius[i]))
            throw std::runtime_error(disk + "has radius " + round_trip_text(s.radius[i]) + "; hard disks need a radius > 0");
        if (s.radius[i] != s.radius[0])
            throw std::runtime_error(disk + "has radius " + round_trip_text(s.radius[i]) + " and particle 0 " +
                                     round_trip_text(s.radius[0]) + ": this sampler takes equal disks only");
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]))
            throw std::runtime_error(disk + "has a non-finite position");
    }
}

void require_inside_walls(const std::string& who, const Scene& scene, const ParticleState<double>& s) {
    const World& w = scene.world;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double r = s.radius[i], slack = hard_disk_overlap_tolerance * 2 * r;
        if (s.x[i] - r < w.xmin - slack || s.x[i] + r > w.xmax + slack || s.y[i] - r < w.ymin - slack ||
            s.y[i] + r > w.ymax + slack)
            throw std::runtime_error(who + ": particle " + std::to_string(i) + " at (" + round_trip_text(s.x[i]) + ", " +
                                     round_trip_text(s.y[i]) + ") with radius " + round_trip_text(r) +
                                     " reaches outside the walls");
    }
}

}  // namespace

void check_sampler_start(const std::string& who, const Scene& scene, const ParticleState<double>& start,
                         const SamplerLimits& limits) {
    if (auto why = outside_sampler_model(scene_features(scene), limits)) throw std::runtime_error(who + ": scene '" + scene.name + "': " + *why);
    if (start.size() == 0) throw std::runtime_error(who + ": scene '" + scene.name + "' has no disks to sample");
    require_equal_movable_disks(who, start);
    if (scene.periodic()) {
        // The overlap search bins positions into the box's cells: wrap them in first.
        ParticleState<double> wrapped = start;
        for (std::size_t i = 0; i < start.size(); ++i) {
            wrapped.x[i] = wrap_into_box(start.x[i], scene.world.xmin, scene.world.width());
            wrapped.y[i] = wrap_into_box(start.y[i], scene.world.ymin, scene.world.height());
        }
        reject_overlapping_disks(who, scene, wrapped);
    } else {
        require_inside_walls(who, scene, start);
        reject_overlapping_disks(who, scene, start);
    }
}

std::int64_t sampler_steps_at(double t, const Scene& scene, std::int64_t total) {
    if (t >= scene.run.duration) return total;
    return std::clamp<std::int64_t>(std::llround(double(total) * (t / scene.run.duration)), 0, total);
}

}  // namespace collide
