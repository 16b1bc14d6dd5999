// The `box2d` backend on cases with exact answers. Tolerances follow from Box2D's solver (see
// docs/box2d-baseline.md): an isolated contact is one constraint, which the first
// sequential-impulse iteration solves exactly, so a binary collision is exact up to float
// rounding (a few ulps of 6e-8 on velocities of order 1: kFloat = 1e-5).
// The cases every backend shares (head-on, walls on all four sides, wall restitution, a stone
// under gravity) are conformance bodies (tests/conformance/test_conformance.cpp); here are
// Box2D's own.
#include <gtest/gtest.h>

#include <box2d/b2_common.h>
#include <box2d/box2d.h>

#include <cmath>
#include <stdexcept>

#include "box2d/box2d_profiler.h"
#include "box2d/box2d_solver.h"
#include "core/scene/option_reader.h"
#include "core/metrics.h"
#include "core/run_driver.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

constexpr double kFloat = 1e-5;

ParticleState<double> run_to(const Scene& scene, const ParticleState<double>& initial, double t,
                             Box2dSolver* solver_out = nullptr) {
    Box2dSolver local;
    Box2dSolver& solver = solver_out ? *solver_out : local;
    solver.load(scene, initial);
    solver.advance_to(t);
    ParticleState<double> s;
    solver.read_state(s);
    return s;
}

TEST(Box2dSolver, SuiteIterationsOptionReplacesTheScenesVelocityIterations) {
    BackendOptions options;
    options.extra["iterations"] = "17";
    Box2dSolver solver(options);
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    solver.load(scene, test::make_state({{3, 2, 1, 0, 0.5, 1}, {7, 2, -1, 0, 0.5, 1}}));
    EXPECT_EQ(solver.options().velocity_iterations, 17);
    EXPECT_EQ(solver.provenance().at("box2d_velocity_iterations"), "17");
    options.extra["iterations"] = "many";
    EXPECT_THROW(Box2dSolver{options}, std::invalid_argument);
}

TEST(Box2dSolver, FreeFlightIsSemiImplicitEulerInSceneUnits) {
    // Radius 0.05 gives the default scale s = 10: positions and speeds must come back unscaled.
    // Box2D integrates v_{k+1} = v_k + h g, x_{k+1} = x_k + h v_{k+1}, so after n steps
    // y_n = y_0 + n h v_0 + g h^2 n (n + 1) / 2.
    Scene scene = test::box_scene(100, 100);
    scene.physics.gravity_y = -2.0;
    scene.run.dt = 0.01;
    Box2dSolver solver;
    const auto s = run_to(scene, test::make_state({{30, 80, 1.5, 0.5, 0.05, 1}}), 1.0, &solver);
    EXPECT_DOUBLE_EQ(solver.units().scale, 10.0);
    const double n = 100, h = 0.01;
    EXPECT_NEAR(s.x[0], 30 + n * h * 1.5, 1e-4);
    EXPECT_NEAR(s.y[0], 80 + n * h * 0.5 - 2.0 * h * h * n * (n + 1) / 2, 1e-4);
    EXPECT_NEAR(s.vy[0], 0.5 - 2.0, kFloat);
}

TEST(Box2dSolver, DampingIsBox2dsImplicitDecay) {
    // Box2D applies v <- v / (1 + h gamma) each step: after n steps v_0 / (1 + h gamma)^n.
    Scene scene = test::box_scene(100, 100);
    scene.physics.damping = 0.5;
    scene.run.dt = 0.01;
    const auto s = run_to(scene, test::make_state({{50, 50, 2, 0, 0.5, 1}}), 1.0);
    EXPECT_NEAR(s.vx[0], 2.0 / std::pow(1 + 0.01 * 0.5, 100), kFloat);
}

TEST(Box2dSolver, SleepingIsOff) {
    // A disk slower than Box2D's sleep tolerance (0.01 m/s) would fall asleep after 0.5 s and
    // stop; with sleeping off it keeps drifting.
    Scene scene = test::box_scene(10, 10);
    scene.run.dt = 1e-2;
    Box2dSolver solver;
    const auto s = run_to(scene, test::make_state({{5, 5, 0.002, 0, 0.5, 1}}), 2.0, &solver);
    EXPECT_NEAR(s.x[0], 5.004, 1e-5);
    EXPECT_EQ(solver.stats().counters.at("sleeping_allowed"), 0.0);
}

TEST(Box2dSolver, TranslationCapIsDetectedAndCounted) {
    // Scale 1 (radius 0.5). At 3000 units/s and dt = 1e-3 the disk would move 3 m per step, but
    // Box2D caps it at b2_maxTranslation = 2 m: it moves 2 per step and is counted each step.
    Scene scene = test::box_scene(1000, 100);
    scene.run.dt = 1e-3;
    Box2dSolver solver;
    const auto s = run_to(scene, test::make_state({{100, 50, 3000, 0, 0.5, 1}, {100, 20, 1000, 0, 0.5, 1}}),
                          0.01, &solver);
    EXPECT_NEAR(s.x[0], 100 + 10 * b2_maxTranslation, 1e-3);
    EXPECT_NEAR(s.x[1], 100 + 10.0, 1e-3);  // 1 m per step: below the cap, untouched
    const auto counters = solver.stats().counters;
    EXPECT_EQ(counters.at("translation_cap_steps"), 10.0);
    EXPECT_EQ(counters.at("translation_cap_body_steps"), 10.0);
}

TEST(Box2dSolver, SubstepsLiftTheTranslationCap) {
    // The same 3000 units/s with 2 Box2D steps per dt: 1.5 m per Box2D step, below the cap.
    Scene scene = test::box_scene(1000, 100);
    scene.run.dt = 1e-3;
    scene.backend_options["box2d"] = {{"substeps", "2"}};
    Box2dSolver solver;
    const auto s = run_to(scene, test::make_state({{100, 50, 3000, 0, 0.5, 1}}), 0.01, &solver);
    EXPECT_NEAR(s.x[0], 100 + 30.0, 1e-3);
    EXPECT_EQ(solver.stats().counters.at("translation_cap_steps"), 0.0);
    EXPECT_EQ(solver.stats().counters.at("box2d_substeps"), 2.0);
    EXPECT_EQ(solver.stats().steps, 10);
}

TEST(Box2dSolver, NoTranslationCapAtOrdinarySpeeds) {
    Scene scene = test::box_scene(10, 4);
    Box2dSolver solver;
    run_to(scene, test::make_state({{3, 2, 1, 0, 0.5, 1}, {7, 2, -1, 0, 0.5, 1}}), 2.0, &solver);
    EXPECT_EQ(solver.stats().counters.at("translation_cap_steps"), 0.0);
}

TEST(Box2dSolver, PeriodicSceneIsRefusedWithTheReason) {
    const Scene scene = test::box_scene(10, 10, Boundary::periodic);
    const auto reason = box2d_supports(scene);
    ASSERT_TRUE(reason.has_value());
    EXPECT_NE(reason->find("periodic"), std::string::npos) << *reason;
    Box2dSolver solver;
    EXPECT_THROW(solver.load(scene, test::make_state({{5, 5, 1, 0, 0.5, 1}})), std::runtime_error);
    EXPECT_FALSE(box2d_supports(test::box_scene(10, 10)).has_value());
}

TEST(Box2dSolver, RestitutionThresholdMakesSlowCollisionsInelastic) {
    // Equal masses meet at relative speed 0.5. Below a threshold of 1 Box2D drops the bounce and
    // solves for zero normal relative velocity: both stop (momentum 0). With threshold 0 they
    // exchange velocities.
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    const auto initial = test::make_state({{4, 2, 0.25, 0, 0.5, 1}, {6, 2, -0.25, 0, 0.5, 1}});
    const auto elastic = run_to(scene, initial, 3.0);
    EXPECT_NEAR(elastic.vx[0], -0.25, kFloat);
    EXPECT_NEAR(elastic.vx[1], 0.25, kFloat);

    scene.backend_options["box2d"] = {{"restitution_threshold", "1"}};
    const auto inelastic = run_to(scene, initial, 3.0);
    EXPECT_NEAR(inelastic.vx[0], 0.0, kFloat);
    EXPECT_NEAR(inelastic.vx[1], 0.0, kFloat);
}

// Newton's cradle (data/scenes/stiff/newtons_cradle.toml): five equal disks touching in a row,
// struck by a sixth at speed 1. The hard-disk answer is a sequence of binary collisions: the
// last disk leaves at 1, the rest stop. Box2D counts exactly touching circles as in contact
// (b2CollideCircles makes a manifold unless |d|^2 > (r_a + r_b)^2), so the whole row is one
// island of five contacts from the first step, and the sequential-impulse iterations solve them
// together, as one simultaneous impact; restitution is applied only where the pair was already
// approaching when the step began (the striker's contact). The row then leaves spread out and
// 9.3 % of the energy is gone (the engines suite's `newtons_cradle` failures of box2d and of
// planck, a port of Box2D, at every dt). Open each gap by 1e-3 and the contacts arise one by
// one, each solved exactly: the textbook answer to float rounding.
ParticleState<double> newtons_cradle(double gap) {
    std::vector<test::DiskSpec> disks{{2.0, 2.0, 1.0, 0.0, 0.5, 1.0}};
    for (int k = 0; k < 5; ++k) disks.push_back({4.0 + k * (1.0 + gap), 2.0, 0.0, 0.0, 0.5, 1.0});
    return test::make_state(disks);
}

TEST(Box2dSolver, ATouchingRowIsOneIslandAndLosesEnergyAsASimultaneousImpact) {
    Scene scene = test::box_scene(20, 4);
    scene.run.dt = 1e-3;
    const auto touching = run_to(scene, newtons_cradle(0.0), 3.0);
    double kinetic = 0;
    for (int i = 0; i < 6; ++i) kinetic += 0.5 * touching.vx[i] * touching.vx[i];
    EXPECT_NEAR(kinetic, 0.5 * (1 - 0.093), 0.5 * 0.005) << "the energy the simultaneous solve loses";
    EXPECT_LT(touching.vx[5], 0.6) << "the last disk should not carry the whole momentum";
    const auto gapped = run_to(scene, newtons_cradle(1e-3), 3.0);
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(gapped.vx[i], 0.0, kFloat) << "disk " << i;
    EXPECT_NEAR(gapped.vx[5], 1.0, kFloat);
}

TEST(Box2dSolver, DiluteElasticGasKeepsItsEnergy) {
    // N = 200 disks of radius 0.2 in a 20 x 20 box (area fraction 6%), e = 1, 5 s. Without
    // forces Box2D leaves velocities bit-for-bit alone between contacts, and it solves an
    // isolated contact exactly (one constraint: the first sequential-impulse iteration), so the
    // energy changes only by the float rounding of each contact's velocity update: ~10 roundings
    // of 6e-8 per velocity, i.e. ~1.2e-6 of the energy of the two disks involved, a share 2/N of
    // the total. Over C ~ 220 contact steps that is at most C (2/N) 1.2e-6 ~ 3e-7: tolerance
    // 1e-6. A step where three disks touch at once, which 8 iterations need not solve as the
    // hard-disk collision, would cost of order 1/N = 5e-3 and fail the test: in a gas this
    // dilute at this dt it should not happen (docs/box2d-baseline.md).
    Scene scene = test::box_scene(20, 20);
    scene.run.dt = 1e-3;
    scene.run.duration = 5.0;
    scene.run.output_interval = 1.0;
    const auto initial = test::random_gas(scene, 200, 0.2, 7);
    Box2dSolver solver;
    const RunResult r = run_scene(scene, solver, initial);
    const double e0 = r.series.front().kinetic_energy, e1 = r.series.back().kinetic_energy;
    EXPECT_GT(r.stats.contacts, 100) << "the run must contain collisions to test anything";
    EXPECT_NEAR(e1, e0, 1e-6 * e0);
    EXPECT_EQ(r.series.back().nonfinite, 0);
}

TEST(Box2dSolver, UnknownOptionStopsTheLoad) {
    Scene scene = test::box_scene(10, 10);
    scene.backend_options["box2d"] = {{"sleep", "false"}};
    Box2dSolver solver;
    EXPECT_THROW(solver.load(scene, test::make_state({{5, 5, 1, 0, 0.5, 1}})), BackendOptionError);
}

// Box2D's own profiler is off (box2d/box2d_profiler.cpp): 400 moving disks stepped 50 times
// take far more than the microsecond b2Timer resolves, so with Box2D's clock the profile's step
// and solve times add up to more than 0; with the clock-free timer they are exactly 0.
TEST(Box2dSolver, TheBuiltInProfilerReadsNoClock) {
    ASSERT_TRUE(box2d_profiler_off());
    b2World world(b2Vec2(0.0f, 0.0f));
    b2CircleShape circle;
    circle.m_radius = 0.4f;
    for (int i = 0; i < 400; ++i) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(float(i % 20), float(i / 20));
        def.linearVelocity.Set(float(i % 7) - 3.0f, float(i % 5) - 2.0f);
        world.CreateBody(&def)->CreateFixture(&circle, 1.0f);
    }
    float step_ms = 0, solve_ms = 0;
    for (int k = 0; k < 50; ++k) {
        world.Step(1e-2f, 8, 3);
        step_ms += world.GetProfile().step;
        solve_ms += world.GetProfile().solve;
    }
    EXPECT_EQ(step_ms, 0.0f);
    EXPECT_EQ(solve_ms, 0.0f);
}

}  // namespace
}  // namespace collide
