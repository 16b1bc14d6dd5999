#include "test_scenes.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace collide::test {

Scene box_scene(double width, double height, Boundary boundary) {
    Scene s;
    s.name = "test_box";
    s.world = World{0, 0, width, height, boundary};
    return s;
}

ParticleState<double> make_state(const std::vector<DiskSpec>& disks) {
    ParticleState<double> s;
    for (const auto& d : disks) s.append_disk(d.x, d.y, d.vx, d.vy, d.radius, d.mass, d.stone);
    return s;
}

ParticleState<double> random_gas(const Scene& scene, std::size_t n, double radius, std::uint64_t seed,
                                 bool allow_overlap) {
    std::mt19937_64 rng(seed);
    const World& w = scene.world;
    std::uniform_real_distribution<double> ux(w.xmin + radius, w.xmax - radius);
    std::uniform_real_distribution<double> uy(w.ymin + radius, w.ymax - radius);
    std::uniform_real_distribution<double> uv(-1.0, 1.0);
    std::vector<DiskSpec> disks;
    std::size_t attempts = 0;
    while (disks.size() < n) {
        if (++attempts > 1000 * n + 1000) throw std::runtime_error("random_gas: packing too dense");
        const double x = ux(rng), y = uy(rng);
        bool free = true;
        for (const auto& d : disks)
            if (!allow_overlap && std::hypot(d.x - x, d.y - y) < 2 * radius) { free = false; break; }
        if (free) disks.push_back({x, y, uv(rng), uv(rng), radius, 1.0});
    }
    return make_state(disks);
}

int brute_force_overlapping_pairs(const Scene& scene, const ParticleState<double>& s) {
    int count = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j];
            if (scene.periodic()) {
                dx -= scene.world.width() * std::round(dx / scene.world.width());
                dy -= scene.world.height() * std::round(dy / scene.world.height());
            }
            const double contact = (s.radius[i] + s.radius[j]) * (1 - 1e-12);
            count += dx * dx + dy * dy < contact * contact;
        }
    return count;
}

std::string scene_file(const std::string& relative) {
    return std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/" + relative;
}

}  // namespace collide::test
