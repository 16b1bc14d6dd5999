#include "core/scene/gas_scene.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "core/scene/scene_loader.h"

namespace collide {
namespace {

constexpr double pi = 3.14159265358979323846;

void check_common(const GasSceneSpec& spec, const char* who) {
    if (spec.count < 1) throw SceneError(std::string(who) + ": count = " + std::to_string(spec.count) + ": expected >= 1");
    if (!(spec.radius > 0) || !(spec.mass > 0) || !(spec.aspect > 0) || !(spec.temperature >= 0))
        throw SceneError(std::string(who) + ": expected radius > 0, mass > 0, aspect > 0 and temperature >= 0");
}

// The box (width, height) in which count disks cover the area fraction: phi = N pi r^2 / (w h)
// with w = aspect * h.
Scene empty_scene(const GasSceneSpec& spec, double& width, double& height) {
    const double area = double(spec.count) * pi * spec.radius * spec.radius / spec.area_fraction;
    height = std::sqrt(area / spec.aspect);
    width = spec.aspect * height;
    Scene scene;
    scene.name = "gas_" + std::to_string(spec.count);
    scene.description = std::to_string(spec.count) + " disks at area fraction " + std::to_string(spec.area_fraction);
    scene.seed = spec.seed;
    scene.world = World{0.0, 0.0, width, height, spec.boundary};
    scene.run = spec.run;
    return scene;
}

GasCase make_lattice_gas(const GasSceneSpec& spec) {
    check_common(spec, "make_gas (lattice)");
    if (!(spec.area_fraction > 0 && spec.area_fraction < pi / 4))
        throw SceneError("make_gas (lattice): area_fraction = " + std::to_string(spec.area_fraction) +
                         ": expected a value in (0, pi/4), the densest a square lattice holds");
    if (spec.aspect != 1) throw SceneError("make_gas (lattice): aspect must be 1 (a square box)");
    GasCase gas;
    double box = 0, height = 0;
    gas.scene = empty_scene(spec, box, height);
    // The square box's edge, as L = sqrt(N pi r^2 / phi) (the same value as the height above,
    // computed as the benchmarks always did, so that their scenes stay the same to the bit).
    box = std::sqrt(double(spec.count) * pi * spec.radius * spec.radius / spec.area_fraction);
    gas.scene.world = World{0.0, 0.0, box, box, spec.boundary};
    const std::int64_t n = spec.count;
    const auto columns = std::int64_t(std::ceil(std::sqrt(double(n))));
    const double spacing = box / double(columns);
    const double jitter = std::max(0.0, 0.25 * (spacing - 2 * spec.radius));

    std::mt19937_64 rng(spec.seed);
    std::uniform_real_distribution<double> shift(-jitter, jitter);
    std::uniform_real_distribution<double> uniform(-spec.uniform_speed, spec.uniform_speed);
    std::normal_distribution<double> gauss(0.0, std::sqrt(spec.temperature / spec.mass));
    std::vector<std::int64_t> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    if (spec.shuffle) std::shuffle(order.begin(), order.end(), rng);
    ParticleState<double>& p = gas.initial;
    p.resize(std::size_t(n));
    for (std::int64_t k = 0; k < n; ++k) {
        const std::size_t i = std::size_t(order[std::size_t(k)]);
        p.x[i] = (double(k % columns) + 0.5) * spacing;
        p.y[i] = (double(k / columns) + 0.5) * spacing;
        if (spec.jitter) {
            p.x[i] += shift(rng);
            p.y[i] += shift(rng);
        }
        if (spec.uniform_velocities) {
            p.vx[i] = uniform(rng);
            p.vy[i] = uniform(rng);
        } else {
            p.vx[i] = gauss(rng);
            p.vy[i] = gauss(rng);
        }
        p.radius[i] = spec.radius;
        p.mass[i] = spec.mass;
        p.inv_mass[i] = 1 / spec.mass;
    }
    if (spec.remove_drift) {
        double px = 0, py = 0;
        for (std::size_t i = 0; i < p.size(); ++i) px += p.vx[i], py += p.vy[i];
        for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] -= px / double(n), p.vy[i] -= py / double(n);
    }
    return gas;
}

}  // namespace

Scene make_gas_scene(const GasSceneSpec& spec) {
    constexpr double rsa_jamming = 0.547;  // random sequential addition in 2D (Feder 1980)
    if (spec.placement != GasPlacement::random)
        throw SceneError("make_gas_scene: a lattice gas has no scene of its own; use make_gas");
    check_common(spec, "make_gas_scene");
    if (!(spec.area_fraction > 0 && spec.area_fraction < rsa_jamming))
        throw SceneError("make_gas_scene: area_fraction = " + std::to_string(spec.area_fraction) +
                         ": expected a value in (0, 0.547), the jamming limit of random sequential addition");
    double width = 0, height = 0;
    Scene scene = empty_scene(spec, width, height);
    ParticleGenerator gas;
    gas.kind = "gas";
    gas.count = spec.count;
    gas.radius = spec.radius;
    gas.mass = spec.mass;
    gas.velocity_kind = "maxwell";
    gas.temperature = spec.temperature;
    scene.generators.push_back(gas);
    return scene;
}

GasCase make_gas(const GasSceneSpec& spec) {
    if (spec.placement == GasPlacement::lattice) return make_lattice_gas(spec);
    GasCase gas;
    gas.scene = make_gas_scene(spec);
    gas.initial = generate_initial_state(gas.scene);
    return gas;
}

}  // namespace collide
