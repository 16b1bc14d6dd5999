#include "core/scene/scene_features.h"

#include <numbers>

namespace collide {
namespace {

bool declares_stones(const Scene& scene) {
    for (const auto& g : scene.generators) {
        if (g.stone) return true;
        for (const auto& d : g.disks)
            if (d.stone) return true;
    }
    return false;
}

}  // namespace

SceneFeatures scene_features(const Scene& scene) {
    SceneFeatures f;
    f.reflecting_walls = !scene.periodic();
    f.gravity = scene.has_gravity();
    f.damping = scene.has_damping();
    f.friction = scene.has_friction();
    f.restitution = scene.physics.restitution;
    f.wall_restitution = scene.physics.wall_restitution;
    f.stones = declares_stones(scene);
    return f;
}

bool uniform_radius(const ParticleState<double>& s) {
    for (double r : s.radius)
        if (r != s.radius.front()) return false;
    return !s.radius.empty();
}

SceneFeatures scene_features(const Scene& scene, const ParticleState<double>& initial) {
    SceneFeatures f = scene_features(scene);
    f.stones = f.moving_stones = false;
    double area = 0;
    for (std::size_t i = 0; i < initial.size(); ++i) {
        if (initial.is_stone(i)) {
            f.stones = true;
            if (initial.vx[i] != 0 || initial.vy[i] != 0) f.moving_stones = true;
        }
        area += std::numbers::pi * initial.radius[i] * initial.radius[i];
    }
    f.uniform_radius = uniform_radius(initial);
    f.area_fraction = area / (scene.world.width() * scene.world.height());
    return f;
}

}  // namespace collide
