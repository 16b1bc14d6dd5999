// Test bodies that every backend must pass (see conformance.h).
#include "conformance.h"

#include <cmath>

#include "tests/support/test_scenes.h"

namespace collide::test {

double conformance_tolerance(const std::string& backend) {
    const std::string precision = find_backend(backend).precision;
    if (precision == "double") return 1e-12;
    return 1e-5;
}

bool Conformance::skip_unless_supported(const Scene& scene) const {
    if (auto reason = backend().supports(scene)) {
        GTEST_LOG_(INFO) << GetParam() << " leaves this case out: " << *reason;
        return true;
    }
    return false;
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

namespace {

Scene two_body_scene() {
    Scene scene = box_scene(10, 4);
    scene.run.dt = 1e-3;
    scene.run.duration = 2.0;
    scene.run.output_interval = 1.0;
    return scene;
}

TEST_P(Conformance, HeadOnEqualMassesExchangeVelocities) {
    const Scene scene = two_body_scene();
    if (skip_unless_supported(scene)) GTEST_SKIP();
    const auto initial = make_state({{3, 2, 1, 0, 0.5, 1}, {7, 2, -1, 0, 0.5, 1}});
    const RunResult r = run(scene, initial);
    // They meet at t = 1.5 and swap velocities; at t = 2 each moves with the other's speed.
    EXPECT_NEAR(r.final_state.vx[0], -1.0, tolerance());
    EXPECT_NEAR(r.final_state.vx[1], 1.0, tolerance());
    EXPECT_NEAR(r.final_state.vy[0], 0.0, tolerance());
    EXPECT_NEAR(r.series.back().kinetic_energy, 1.0, tolerance());
}

TEST_P(Conformance, HeadOnMassRatioTenFollowsElasticFormula) {
    const Scene scene = two_body_scene();
    if (skip_unless_supported(scene)) GTEST_SKIP();
    // Contact at t = 0.5 (gap 0.5 closed at speed 1).
    const auto initial = make_state({{5.5, 2, 1, 0, 0.5, 1}, {7, 2, 0, 0, 0.5, 10}});
    const RunResult r = run(scene, initial);
    // v1' = (m1 - m2)/(m1 + m2) u1 = -9/11, v2' = 2 m1/(m1 + m2) u1 = 2/11.
    EXPECT_NEAR(r.final_state.vx[0], -9.0 / 11.0, tolerance());
    EXPECT_NEAR(r.final_state.vx[1], 2.0 / 11.0, tolerance());
}

TEST_P(Conformance, MomentumAndEnergyOfPeriodicElasticGas) {
    Scene scene = box_scene(20, 20, Boundary::periodic);
    scene.run.dt = 2e-3;
    scene.run.duration = 0.5;
    scene.run.output_interval = 0.25;
    if (skip_unless_supported(scene)) GTEST_SKIP();
    const auto initial = random_gas(scene, 150, 0.4, 3);
    const RunResult r = run(scene, initial);
    const Metrics &a = r.series.front(), &b = r.series.back();
    // Momentum: every pair impulse is equal and opposite, so only rounding changes it.
    double momentum_scale = 0;
    for (std::size_t i = 0; i < initial.size(); ++i) momentum_scale += std::hypot(initial.vx[i], initial.vy[i]);
    EXPECT_NEAR(b.momentum_x, a.momentum_x, tolerance() * momentum_scale);
    EXPECT_NEAR(b.momentum_y, a.momentum_y, tolerance() * momentum_scale);
    EXPECT_GT(r.stats.contacts, 0);
    EXPECT_EQ(b.nonfinite, 0);
}

TEST_P(Conformance, StoneNeverMoves) {
    Scene scene = box_scene(10, 10);
    scene.run.dt = 1e-3;
    scene.run.duration = 1.0;
    scene.run.output_interval = 0.5;
    if (skip_unless_supported(scene)) GTEST_SKIP();
    // Two disks fly into a stone in the middle.
    const auto initial = make_state({{5, 5, 0, 0, 1.0, 1, true}, {2, 5, 4, 0, 0.5, 1}, {5, 8, 0, -4, 0.5, 1}});
    const RunResult r = run(scene, initial);
    EXPECT_EQ(r.final_state.x[0], 5.0);
    EXPECT_EQ(r.final_state.y[0], 5.0);
    EXPECT_EQ(r.final_state.vx[0], 0.0);
    EXPECT_LT(r.final_state.vx[1], 0.0) << "the disk should have bounced off the stone";
    EXPECT_GT(r.final_state.vy[2], 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllBackends, Conformance, ::testing::ValuesIn(backend_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace collide::test
