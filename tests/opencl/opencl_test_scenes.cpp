#include "opencl_test_scenes.h"

#include <stdexcept>

#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

Scene short_run(Scene scene, double dt, int steps) {
    scene.run.dt = dt;
    scene.run.duration = dt * steps;
    scene.run.output_interval = scene.run.duration;
    return scene;
}

}  // namespace

std::vector<OpenclCase> opencl_cases(int steps) {
    std::vector<OpenclCase> cases;

    Scene reflect = short_run(box_scene(20, 20), 2e-3, steps);
    cases.push_back({"reflecting gas", reflect, random_gas(reflect, 300, 0.4, 11)});

    Scene periodic = short_run(box_scene(20, 20, Boundary::periodic), 2e-3, steps);
    cases.push_back({"periodic gas", periodic, random_gas(periodic, 300, 0.4, 12)});

    Scene settling = short_run(box_scene(20, 20), 4e-3, steps);
    settling.run.order = StepOrder::integrate_first;
    settling.run.substeps = 4;
    settling.physics.gravity_y = -9.81;
    settling.physics.friction = 0.3;
    settling.physics.damping = 0.2;
    settling.physics.restitution = 0.8;
    settling.physics.wall_restitution = 0.9;
    cases.push_back({"gravity, friction, damping (integrate-first)", settling, random_gas(settling, 300, 0.4, 13)});

    // Every third disk is smaller (polydisperse: per-pair contact distance), every tenth a stone.
    Scene mixed = short_run(box_scene(20, 20), 2e-3, steps);
    ParticleState<double> disks = random_gas(mixed, 300, 0.4, 14);
    for (std::size_t i = 0; i < disks.size(); ++i) {
        if (i % 3 == 0) disks.radius[i] = 0.25;
        if (i % 10 == 0) disks.inv_mass[i] = 0;
    }
    cases.push_back({"polydisperse with stones", mixed, disks});
    return cases;
}

const BackendInfo& backend(const std::string& name) {
    for (const auto& b : all_backends())
        if (b.name == name) return b;
    throw std::invalid_argument("no backend named " + name);
}

}  // namespace collide::test
