#include "gas_scene.h"

#include <cmath>
#include <string>

#include "scene_loader.h"

namespace collide {

Scene make_gas_scene(const GasSceneSpec& spec) {
    constexpr double pi = 3.14159265358979323846;
    constexpr double rsa_jamming = 0.547;  // random sequential addition in 2D (Feder 1980)
    if (spec.count < 1) throw SceneError("make_gas_scene: count = " + std::to_string(spec.count) + ": expected >= 1");
    if (!(spec.radius > 0) || !(spec.mass > 0) || !(spec.aspect > 0) || !(spec.temperature >= 0))
        throw SceneError("make_gas_scene: expected radius > 0, mass > 0, aspect > 0 and temperature >= 0");
    if (!(spec.area_fraction > 0 && spec.area_fraction < rsa_jamming))
        throw SceneError("make_gas_scene: area_fraction = " + std::to_string(spec.area_fraction) +
                         ": expected a value in (0, 0.547), the jamming limit of random sequential addition");

    // phi = N pi r^2 / (w h) with w = aspect * h.
    const double area = double(spec.count) * pi * spec.radius * spec.radius / spec.area_fraction;
    const double height = std::sqrt(area / spec.aspect), width = spec.aspect * height;

    Scene scene;
    scene.name = "gas_" + std::to_string(spec.count);
    scene.description = std::to_string(spec.count) + " disks at area fraction " + std::to_string(spec.area_fraction);
    scene.seed = spec.seed;
    scene.world = World{0.0, 0.0, width, height, spec.boundary};
    scene.run = spec.run;

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

}  // namespace collide
