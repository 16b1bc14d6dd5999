// The `chipmunk` backend on cases with exact answers. Chipmunk computes in double, and an
// isolated contact is one constraint, which the first sequential-impulse iteration solves
// exactly; so binary collisions and free flight are exact up to double rounding (kDouble).
// The cases every backend shares are conformance bodies (tests/conformance/); here are
// Chipmunk's own: its integrator, its damping law, its contact law and what it refuses.
#include <gtest/gtest.h>

#include <chipmunk/chipmunk.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "chipmunk/chipmunk_solver.h"
#include "chipmunk/chipmunk_space.h"
#include "core/scene/option_reader.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

constexpr double kDouble = 1e-12;

ParticleState<double> run_to(const Scene& scene, const ParticleState<double>& initial, double t,
                             ChipmunkSolver* solver_out = nullptr) {
    ChipmunkSolver local;
    ChipmunkSolver& solver = solver_out ? *solver_out : local;
    solver.load(scene, initial);
    solver.advance_to(t);
    ParticleState<double> s;
    solver.read_state(s);
    return s;
}

TEST(ChipmunkSolver, FreeFlightIsSemiImplicitEuler) {
    // cpSpaceStep moves the bodies first (cpBodyUpdatePosition, with the velocity the last
    // step's solver left), then adds gravity (cpBodyUpdateVelocity) and solves the contacts:
    // x_{k+1} = x_k + h v_k, v_{k+1} = v_k + h g, so y_n = y_0 + n h v_0 + g h^2 n (n - 1) / 2.
    Scene scene = test::box_scene(100, 100);
    scene.physics.gravity_y = -2.0;
    scene.run.dt = 0.01;
    const auto s = run_to(scene, test::make_state({{30, 80, 1.5, 0.5, 0.05, 1}}), 1.0);
    const double n = 100, h = 0.01;
    EXPECT_NEAR(s.x[0], 30 + n * h * 1.5, 1e-10);
    EXPECT_NEAR(s.y[0], 80 + n * h * 0.5 - 2.0 * h * h * n * (n - 1) / 2, 1e-10);
    EXPECT_NEAR(s.vy[0], 0.5 - 2.0, kDouble);
}

TEST(ChipmunkSolver, DampingIsTheExactExponentialDecay) {
    // Scene damping c (dv/dt = -c v) becomes Chipmunk's kept fraction per second e^{-c}, which
    // it applies as v <- v (e^{-c})^h: after t = 1, v_0 e^{-c} whatever the step.
    Scene scene = test::box_scene(100, 100);
    scene.physics.damping = 0.5;
    scene.run.dt = 0.01;
    const auto s = run_to(scene, test::make_state({{50, 50, 2, 0, 0.5, 1}}), 1.0);
    EXPECT_NEAR(s.vx[0], 2.0 * std::exp(-0.5), 1e-10);
}

TEST(ChipmunkSolver, SlowCollisionsBounceAsFastOnes) {
    // Chipmunk has no restitution threshold (Box2D drops the bounce below 1 m/s): equal disks at
    // relative speed 0.02 exchange velocities.
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    const auto s = run_to(scene, test::make_state({{4.49, 2, 0.01, 0, 0.5, 1}, {5.51, 2, -0.01, 0, 0.5, 1}}), 2.0);
    EXPECT_NEAR(s.vx[0], -0.01, kDouble);
    EXPECT_NEAR(s.vx[1], 0.01, kDouble);
}

TEST(ChipmunkSolver, RestitutionBetweenDisksIsTheScenesWhenTunedAndSquaredWhenShipped) {
    // Head-on at relative speed 2 with e = 0.5: the separation speed is e * 2 = 1 under the
    // scene's law; Chipmunk's own product rule gives both shapes e, so e^2 * 2 = 0.5.
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    scene.physics.restitution = 0.5;
    const auto initial = test::make_state({{4, 2, 1, 0, 0.5, 1}, {6, 2, -1, 0, 0.5, 1}});
    const auto tuned = run_to(scene, initial, 1.5);
    EXPECT_NEAR(tuned.vx[1] - tuned.vx[0], 1.0, kDouble);
    scene.backend_options["chipmunk"] = {{"preset", "shipped"}};
    const auto shipped = run_to(scene, initial, 1.5);
    EXPECT_NEAR(shipped.vx[1] - shipped.vx[0], 0.5, kDouble);
}

TEST(ChipmunkSolver, WallsTakeTheWallRestitution) {
    // A disk at speed 1 hits the right wall (wall restitution 0.8, disk restitution 1): it
    // comes back at 0.8.
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    scene.physics.wall_restitution = 0.8;
    const auto s = run_to(scene, test::make_state({{8, 2, 1, 0, 0.5, 1}}), 3.0);
    EXPECT_NEAR(s.vx[0], -0.8, kDouble);
}

TEST(ChipmunkSolver, CountsEachPairCollisionOnce) {
    // One head-on collision: one contact, however many steps the pair stays in touch (with
    // slop 0, while the correction separates it); the wall contacts are not counted.
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    ChipmunkSolver solver;
    run_to(scene, test::make_state({{4, 2, 1, 0, 0.5, 1}, {6, 2, -1, 0, 0.5, 1}}), 1.0, &solver);
    EXPECT_EQ(solver.stats().contacts, 1);
    ChipmunkSolver lone;
    run_to(scene, test::make_state({{8, 2, 1, 0, 0.5, 1}}), 3.0, &lone);
    EXPECT_EQ(lone.stats().contacts, 0);  // it hit the wall only
}

TEST(ChipmunkSolver, ATouchingRowIsStruckOneContactAtATime) {
    // Newton's cradle: five equal disks touching in a row, struck by a sixth at speed 1.
    // Chipmunk's circle test makes a contact only for |d| < r_a + r_b, strictly, so exactly
    // touching disks are not in contact until the struck one moves into its neighbour: the
    // collisions come one at a time, each an isolated contact solved exactly, and the last disk
    // leaves at 1 (the textbook answer; Box2D, which counts touching as contact, does not:
    // Box2dSolver.ATouchingRowIsOneIslandAndLosesEnergyAsASimultaneousImpact).
    Scene scene = test::box_scene(20, 4);
    scene.run.dt = 1e-3;
    std::vector<test::DiskSpec> disks{{2.0, 2.0, 1.0, 0.0, 0.5, 1.0}};
    for (int k = 0; k < 5; ++k) disks.push_back({4.0 + k, 2.0, 0.0, 0.0, 0.5, 1.0});
    const auto s = run_to(scene, test::make_state(disks), 3.0);
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(s.vx[i], 0.0, kDouble) << "disk " << i;
    EXPECT_NEAR(s.vx[5], 1.0, kDouble);
}

TEST(ChipmunkSolver, StoneNeverMovesAndDeflects) {
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    const auto initial = test::make_state({{4, 2, 1, 0, 0.5, 1}, {6, 2, 0, 0, 0.5, 1, true}});
    const auto s = run_to(scene, initial, 2.0);
    EXPECT_EQ(s.x[1], 6.0);
    EXPECT_NEAR(s.vx[0], -1.0, kDouble);
}

TEST(ChipmunkSolver, SuiteIterationsOptionReplacesTheScenes) {
    BackendOptions options;
    options.extra["iterations"] = "17";
    ChipmunkSolver solver(options);
    Scene scene = test::box_scene(10, 4);
    run_to(scene, test::make_state({{3, 2, 1, 0, 0.5, 1}}), 0.1, &solver);
    EXPECT_EQ(solver.options().iterations, 17);
    EXPECT_EQ(solver.provenance().at("chipmunk_iterations"), "17");
    options.extra["iterations"] = "many";
    EXPECT_THROW(ChipmunkSolver{options}, std::invalid_argument);
}

TEST(ChipmunkSolver, PeriodicSceneIsRefusedWithTheReason) {
    const Scene scene = test::box_scene(10, 10, Boundary::periodic);
    const auto reason = chipmunk_supports(scene);
    ASSERT_TRUE(reason.has_value());
    EXPECT_NE(reason->find("periodic"), std::string::npos) << *reason;
    ChipmunkSolver solver;
    EXPECT_THROW(solver.load(scene, test::make_state({{5, 5, 1, 0, 0.5, 1}})), std::runtime_error);
}

TEST(ChipmunkSolver, ReloadingStartsAFreshSpace) {
    Scene scene = test::box_scene(10, 4);
    scene.run.dt = 1e-3;
    ChipmunkSolver solver;
    run_to(scene, test::make_state({{3, 2, 1, 0, 0.5, 1}}), 1.0, &solver);
    const auto again = run_to(scene, test::make_state({{3, 2, 1, 0, 0.5, 1}, {7, 2, 0, 0, 0.5, 1}}), 1.0, &solver);
    ASSERT_EQ(again.size(), 2u);
    EXPECT_NEAR(again.x[0], 4.0, 1e-10);
    EXPECT_EQ(solver.time(), 1.0);
}

// In a fresh process (the threadsafe death-test style re-runs this test alone), the first space
// must leave stdout empty: Debian's debug-enabled Chipmunk prints its banner there otherwise.
TEST(ChipmunkSpace, FirstSpaceKeepsTheBannerOffStdout) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            char path[] = "/tmp/collide-chipmunk-stdout-XXXXXX";
            const int fd = ::mkstemp(path);
            std::fflush(stdout);  // what the test framework printed so far is not the space's
            ::dup2(fd, STDOUT_FILENO);
            cpSpaceFree(new_chipmunk_space());
            std::fflush(stdout);
            struct stat st {};
            ::fstat(fd, &st);
            ::unlink(path);
            std::_Exit(st.st_size == 0 ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "Chipmunk");
}

}  // namespace
}  // namespace collide
