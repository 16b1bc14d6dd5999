// The few-body cases and the fixture's helpers shared by the conformance tests.
#include <cmath>
#include <stdexcept>

#include "conformance.h"
#include "tests/support/test_scenes.h"

namespace collide::test {

double conformance_tolerance(const std::string& backend) {
    return find_backend(backend).single_precision() ? 1e-5 : 1e-12;
}

// What the backend declares (BackendInfo::exact), not its name.
bool is_exact(const std::string& backend) { return find_backend(backend).exact; }

bool Conformance::skip_unless_supported(const Scene& scene) const {
    if (backend().sampler) {  // the conformance cases are dynamics: bounces, times, invariants
        GTEST_LOG_(INFO) << GetParam() << " leaves this case out: " << backend().sampler_left_out();
        return true;
    }
    if (auto reason = backend().supports(scene)) {
        GTEST_LOG_(INFO) << GetParam() << " leaves this case out: " << *reason;
        return true;
    }
    return false;
}

bool Conformance::skip_unless_exact(const Scene& scene) const {
    if (!is_exact(GetParam())) {
        GTEST_LOG_(INFO) << GetParam() << " leaves this case out: it checks exact event times, which the time-stepped "
                                          "backends meet only to O(dt) (their own tests check their rules)";
        return true;
    }
    return skip_unless_supported(scene);
}

RunResult Conformance::run(const Scene& scene, const ParticleState<double>& initial) const {
    auto solver = backend().create(BackendOptions{});
    return run_scene(scene, *solver, initial);
}

std::vector<std::string> backend_names() {
    std::vector<std::string> names;
    for (const auto& b : all_backends()) names.push_back(b.name);
    return names;
}

std::string test_name(const std::string& backend) {
    std::string name = backend;
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

namespace {

// The disks are also written into the scene as a list generator, as a scene file would hold
// them, so that a backend's supports() sees what the scene contains (stones, for one).
ConformanceCase make_case(const std::string& name, Scene scene, const std::vector<DiskSpec>& disks, double duration) {
    scene.name = name;
    scene.run.dt = 1e-3;
    scene.run.duration = duration;
    scene.run.output_interval = duration / 4;
    ParticleGenerator list;
    list.kind = "list";
    for (const DiskSpec& d : disks) list.disks.push_back({d.x, d.y, d.vx, d.vy, d.radius, d.mass, d.stone});
    scene.generators.push_back(list);
    return {name, scene, make_state(disks)};
}

std::vector<ConformanceCase> make_cases() {
    std::vector<ConformanceCase> cases;
    // Equal disks meet head-on at t = 1.5 and swap velocities.
    cases.push_back(make_case("head_on", box_scene(10, 4), {{3, 2, 1, 0, 0.5, 1}, {7, 2, -1, 0, 0.5, 1}}, 2.0));
    // Mass ratio 10, contact at t = 0.5 (gap 0.5 closed at speed 1).
    cases.push_back(make_case("mass_ratio_10", box_scene(10, 4), {{5.5, 2, 1, 0, 0.5, 1}, {7, 2, 0, 0, 0.5, 10}}, 2.0));
    // Disk i (m = 1) at (5, 5) moving (1, 0) meets disk j (m = 2) at rest at (8, 5.5), off-centre.
    cases.push_back(make_case("glancing", box_scene(20, 20), {{5, 5, 1, 0, 0.5, 1}, {8, 5.5, 0, 0, 0.5, 2}}, 4.0));
    // Two disks fly into a stone in the middle.
    cases.push_back(make_case("stone", box_scene(10, 10),
                              {{5, 5, 0, 0, 1.0, 1, true}, {2, 5, 4, 0, 0.5, 1}, {5, 8, 0, -4, 0.5, 1}}, 1.0));
    // A disk falls onto a stone under gravity (speed ~9 at impact, t ~ 0.64) and bounces.
    ConformanceCase fall =
        make_case("stone_under_gravity", box_scene(10, 10), {{5, 3, 0, 0, 1.0, 1, true}, {5, 8, 0, -3, 0.5, 1}}, 1.5);
    fall.scene.physics.gravity_y = -9.81;
    cases.push_back(fall);
    // One disk into each of the four walls; each reaches its wall at t = 4.75.
    cases.push_back(make_case("four_walls", box_scene(20, 20),
                              {{10, 3, 2, 0, 0.5, 1}, {10, 17, -2, 0, 0.5, 1}, {3, 10, 0, -2, 0.5, 1}, {17, 10, 0, 2, 0.5, 1}},
                              5.0));
    // Wall restitution 0.5: contact with x = 0 at t = 0.25, vx -2 -> +1.
    ConformanceCase wall_e = make_case("wall_restitution", box_scene(10, 10), {{1, 5, -2, 0.5, 0.5, 1}}, 1.0);
    wall_e.scene.physics.wall_restitution = 0.5;
    cases.push_back(wall_e);
    // Disks at x = 0.7 and 9.3 in a periodic box of width 10 are 1.4 apart through the side.
    cases.push_back(make_case("periodic_pair", box_scene(10, 10, Boundary::periodic),
                              {{0.7, 5, -1, 0, 0.5, 1}, {9.3, 5, 1, 0, 0.5, 1}}, 0.5));
    // Free flight through two periodic sides.
    cases.push_back(make_case("periodic_flight", box_scene(10, 10, Boundary::periodic), {{9, 9, 3, 2.5, 0.5, 1}}, 2.0));
    // A disk dropped from rest at y = 10 under gravity bounces on the floor.
    ConformanceCase drop = make_case("gravity_drop", box_scene(10, 20), {{5, 10, 0, 0, 0.5, 2}}, 0.0);
    drop.scene.physics.gravity_y = -9.81;
    drop.scene.run.duration = std::sqrt(2 * 9.5 / 9.81) + 0.3;
    drop.scene.run.output_interval = drop.scene.run.duration / 4;
    cases.push_back(drop);
    // Four disks thrown about a box under gravity: parabolas, pair collisions while falling (the
    // relative motion stays straight), walls and cell crossings. No closed form: the exact
    // solvers must agree with each other and keep the total energy.
    ConformanceCase thrown = make_case("gravity_four", box_scene(8, 8),
                                       {{1.5, 2, 3, 4, 0.5, 1}, {4, 5, -2, 1, 0.6, 2}, {6, 1.5, -1, 5, 0.4, 1},
                                        {2, 6, 2, -1, 0.5, 3}},
                                       3.0);
    thrown.scene.physics.gravity_y = -9.81;
    cases.push_back(thrown);
    // A striker hits a row of four touching disks (Newton's cradle): simultaneous collisions.
    cases.push_back(make_case("newtons_cradle", box_scene(20, 4),
                              {{1, 2, 1, 0, 0.5, 1}, {3, 2, 0, 0, 0.5, 1}, {4, 2, 0, 0, 0.5, 1}, {5, 2, 0, 0, 0.5, 1},
                               {6, 2, 0, 0, 0.5, 1}},
                              2.0));
    // The billiard that counts digits of pi (Galperin 2003), mass ratio 100^3: 3141 collisions.
    cases.push_back(make_case("pi_billiard", box_scene(2000, 2), {{2, 1, 0, 0, 0.5, 1}, {4, 1, -1, 0, 0.5, 1e6}}, 1000.0));
    // A small periodic gas: 150 disks, chaos and minimum images.
    ConformanceCase gas{"periodic_gas", box_scene(20, 20, Boundary::periodic), {}};
    gas.scene.name = gas.name;
    gas.scene.run.dt = 2e-3;
    gas.scene.run.duration = 0.5;
    gas.scene.run.output_interval = 0.25;
    gas.initial = random_gas(gas.scene, 150, 0.4, 3);
    cases.push_back(gas);
    return cases;
}

}  // namespace

const std::vector<ConformanceCase>& conformance_cases() {
    static const std::vector<ConformanceCase> cases = make_cases();
    return cases;
}

const ConformanceCase& conformance_case(const std::string& name) {
    for (const auto& c : conformance_cases())
        if (c.name == name) return c;
    throw std::invalid_argument("no conformance case '" + name + "'");
}

}  // namespace collide::test
