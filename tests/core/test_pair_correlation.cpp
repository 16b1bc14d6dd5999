// g(r) near contact: 1 for an ideal gas (uncorrelated points), and the contact route to Z
// against the collision virial of an event-driven run of the same hard-disk fluid.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/backend_registry.h"
#include "core/run_driver.h"
#include "core/structure/pair_correlation.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

// Uniform, independent points: every bin's g is 1 up to counting noise (~0.6 % a bin here).
TEST(PairCorrelation, IdealGasIsUncorrelated) {
    const Scene scene = test::box_scene(20, 20, Boundary::periodic);
    ContactCorrelation g(1.0, 0.5, 5);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 20);
    for (int c = 0; c < 200; ++c) {
        ParticleState<double> s;
        for (int i = 0; i < 400; ++i) s.append_disk(u(rng), u(rng), 0, 0, 0.5, 1, false);
        g.add(scene.world, s);
    }
    for (std::size_t b = 0; b < 5; ++b) EXPECT_NEAR(g.g(b), 1.0, 0.03) << "bin " << b;
    EXPECT_NEAR(g.contact(), 1.0, 0.05);
}

// The same equilibrium fluid (eta = 0.4, 200 disks) by two routes: 1 + 2 eta g(d) from the
// configurations at the outputs, and the collision virial recorded by run_scene. They agree
// within their errors (a few percent of Z = 2.8 for this run length).
TEST(PairCorrelation, ContactRouteAgreesWithTheCollisionVirial) {
    const double radius = 0.5, eta = 0.4;
    const double box = std::sqrt(200 * std::numbers::pi * radius * radius / eta);
    Scene scene = test::box_scene(box, box, Boundary::periodic);
    scene.run.duration = 100;
    scene.run.output_interval = 0.25;
    const auto initial = test::random_gas(scene, 200, radius, 3);
    ContactCorrelation g(2 * radius, 0.1, 5);
    RunOptions options;
    options.on_state = [&](const ParticleState<double>& state, const Metrics& m) {
        if (m.time >= 20) g.add(scene.world, state);  // after the approach to equilibrium
    };
    auto solver = find_backend("event").create({});
    const RunResult run = run_scene(scene, *solver, initial, options);
    const double z_virial = run.stats.counters.at("beta_pressure") * box * box / 200 / (4 * radius * radius);
    EXPECT_NEAR(g.compressibility(), z_virial, 0.05 * z_virial);
    EXPECT_NEAR(z_virial, 2.83, 0.1);  // Henderson's (1 + eta^2 / 8) / (1 - eta)^2 = 2.83
}

}  // namespace
}  // namespace collide
