// The `event` backend: free flight between outputs, restitution, a long gas run, its round-off
// rules and its input checks. The cases with exact answers that every backend shares (head-on,
// glancing, stones, walls, periodic sides, gravity, Newton's cradle, the pi billiard) are
// conformance bodies (tests/conformance/test_conformance.cpp), run on `event` and `event-plain`.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "core/metrics.h"
#include "reference/event/event_solver.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using test::box_scene;
using test::make_state;

ParticleState<double> run_to(const Scene& scene, const ParticleState<double>& initial, double t,
                             SolverStats* stats = nullptr) {
    EventSolver solver;
    solver.load(scene, initial);
    solver.advance_to(t);
    ParticleState<double> out;
    solver.read_state(out);
    if (stats) *stats = solver.stats();
    return out;
}

// Expects `f` to throw std::runtime_error whose message contains every one of `parts`.
template <typename F>
void expect_error(F&& f, std::initializer_list<std::string> parts) {
    try {
        f();
        ADD_FAILURE() << "expected an error";
    } catch (const std::exception& e) {
        for (const auto& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    }
}

TEST(EventSolver, OutputBetweenEventsIsFreeFlight) {
    EventSolver solver;
    solver.load(box_scene(10, 4), make_state({{3, 2, 1, 0.25, 0.5, 1}}));
    ParticleState<double> s;
    for (double t : {0.5, 1.0, 1.0, 2.0}) {
        solver.advance_to(t);
        solver.read_state(s);
        EXPECT_NEAR(s.x[0], 3 + t, 1e-12);
        EXPECT_NEAR(s.y[0], 2 + 0.25 * t, 1e-12);
    }
    EXPECT_THROW(solver.advance_to(1.0), std::invalid_argument);
}

TEST(EventSolver, InelasticHeadOnFollowsRestitution) {
    Scene scene = box_scene(10, 4);
    scene.physics.restitution = 0.5;
    const auto s = run_to(scene, make_state({{3, 2, 1, 0, 0.5, 1}, {7, 2, -1, 0, 0.5, 1}}), 2.0);
    // Equal masses, u = 2: each leaves with e * 1 = 0.5 in the reverse direction.
    EXPECT_NEAR(s.vx[0], -0.5, 1e-12);
    EXPECT_NEAR(s.vx[1], 0.5, 1e-12);
}

TEST(EventSolver, PeriodicGasConservesEnergyAndMomentumOverMillionCollisions) {
    const Scene scene = box_scene(51.2, 51.2, Boundary::periodic);  // 1000 disks of r = 0.5: area fraction 0.3
    const auto initial = test::random_gas(scene, 1000, 0.5, 11);
    EventSolver solver;
    solver.load(scene, initial);
    double t = 0;
    while (solver.stats().contacts < 1000000) solver.advance_to(t += 20);
    ParticleState<double> s;
    solver.read_state(s);
    const Metrics a = compute_metrics(scene, initial, 0), b = compute_metrics(scene, s, t);
    double momentum_scale = 0;
    for (std::size_t i = 0; i < initial.size(); ++i) momentum_scale += std::hypot(initial.vx[i], initial.vy[i]);
    EXPECT_NEAR(b.kinetic_energy, a.kinetic_energy, 1e-10 * a.kinetic_energy);
    EXPECT_NEAR(b.momentum_x, a.momentum_x, 1e-10 * momentum_scale);
    EXPECT_NEAR(b.momentum_y, a.momentum_y, 1e-10 * momentum_scale);
    EXPECT_EQ(b.overlapping_pairs, 0);
}

// --- Input checks ---------------------------------------------------------------------

TEST(EventSolverInput, OverlappingInitialStateNamesThePair) {
    expect_error([] { run_to(box_scene(10, 10), make_state({{2, 2, 0, 0, 0.5, 1}, {5, 5, 0, 0, 0.5, 1}, {5.6, 5, 0, 0, 0.5, 1}}), 1); },
                 {"particles 1 and 2", "overlap by 0.4"});
}

TEST(EventSolverInput, TouchingInitialStateIsAccepted) {
    EXPECT_NO_THROW(run_to(box_scene(10, 10), make_state({{5, 5, 0, 0, 0.5, 1}, {6, 5, 0, 0, 0.5, 1}}), 1));
}

TEST(EventSolverInput, ParticleOutsideWallsIsRejected) {
    expect_error([] { run_to(box_scene(10, 10), make_state({{5, 5, 0, 0, 0.5, 1}, {9.8, 5, 0, 0, 0.5, 1}}), 1); },
                 {"particle 1", "outside the walls"});
}

TEST(EventSolverInput, RestitutionAboveOneIsRejected) {
    Scene scene = box_scene(10, 10);
    scene.physics.restitution = 1.2;
    expect_error([&] { run_to(scene, make_state({{5, 5, 0, 0, 0.5, 1}}), 1); }, {"restitution", "1.2"});
}

TEST(EventSolverInput, ZeroRadiusIsRejected) {
    expect_error([] { run_to(box_scene(10, 10), make_state({{5, 5, 0, 0, 0.5, 1}, {2, 2, 0, 0, 0.0, 1}}), 1); },
                 {"particle 1", "radius 0"});
}

TEST(EventSolverInput, FrictionAndDampingAreLeftOutWithReason) {
    Scene scene = box_scene(10, 10);
    EXPECT_FALSE(EventSolver::supports(scene));
    scene.physics.friction = 0.3;
    ASSERT_TRUE(EventSolver::supports(scene));
    EXPECT_NE(EventSolver::supports(scene)->find("friction"), std::string::npos);
    expect_error([&] { run_to(scene, make_state({{5, 5, 0, 0, 0.5, 1}}), 1); }, {"friction"});
    scene.physics.friction = 0;
    scene.physics.damping = 0.1;
    ASSERT_TRUE(EventSolver::supports(scene));
    EXPECT_NE(EventSolver::supports(scene)->find("damping"), std::string::npos);
}

TEST(EventSolverInput, UnknownBackendOptionIsRejected) {
    Scene scene = box_scene(10, 10);
    scene.backend_options["event"]["t_c"] = "1e-3";
    expect_error([&] { run_to(scene, make_state({{5, 5, 0, 0, 0.5, 1}}), 1); }, {"t_c", "known: tc, renumber_interval"});
}

TEST(EventSolverInput, RenumberIntervalMustBeAPositiveWholeNumber) {
    for (const char* bad : {"0", "-3", "2.5", "7x", "many"}) {
        Scene scene = box_scene(10, 10);
        scene.backend_options["event"]["renumber_interval"] = bad;
        expect_error([&] { run_to(scene, make_state({{5, 5, 0, 0, 0.5, 1}}), 1); },
                     {"renumber_interval", bad, "whole number of events >= 1"});
    }
}

// Cells narrower than the largest contact distance would hide partners outside the 3x3 cells
// around a disk: such a cell_size is refused, naming the smallest allowed edge.
TEST(EventSolverInput, CellSizeBelowTheContactDistanceIsRefused) {
    for (const char* bad : {"0.99", "0", "-1", "wide"}) {
        Scene scene = box_scene(10, 10);
        scene.backend_options["event"]["cell_size"] = bad;
        expect_error([&] { run_to(scene, make_state({{5, 5, 0, 0, 0.5, 1}}), 1); },
                     {"cell_size", bad, "largest contact distance 2 r_max = 1"});
    }
}

TEST(EventSolverInput, PrefetchMustBeAutoOnOrOff) {
    for (const char* bad : {"yes", "1", "", "On"}) {
        Scene scene = box_scene(10, 10);
        scene.backend_options["event"]["prefetch"] = bad;
        expect_error([&] { run_to(scene, make_state({{5, 5, 0, 0, 0.5, 1}}), 1); },
                     {"prefetch", "expected \"auto\", \"on\" or \"off\""});
    }
}

// --- Inelastic collapse and the progress guard -----------------------------------------

// A disk dropped on a floor with wall restitution 0.5 bounces with intervals shrinking by 0.5
// each time: infinitely many bounces in finite time (inelastic collapse at a wall).
Scene bouncing_scene(const std::string& tc) {
    Scene scene = box_scene(4, 10);
    scene.physics.gravity_y = -1;
    scene.physics.wall_restitution = 0.5;
    scene.backend_options["event"]["tc"] = tc;
    return scene;
}

TEST(EventSolverCollapse, WithoutTcModelTheStalledLoopIsReported) {
    expect_error([] { run_to(bouncing_scene("0"), make_state({{2, 3, 0, 0, 0.5, 1}}), 20); },
                 {"no progress", "particle 0", "wall 2"});
}

TEST(EventSolverCollapse, TcModelKeepsTheBouncingDiskGoing) {
    SolverStats stats;
    const auto s = run_to(bouncing_scene("1e-3"), make_state({{2, 3, 0, 0, 0.5, 1}}), 20, &stats);
    EXPECT_GT(stats.counters["tc_elastic"], 0);
    // Once bounces come closer than t_c they are elastic: the disk keeps hopping with a
    // vertical speed of about g t_c / 2, never below the floor.
    EXPECT_GE(s.y[0], 0.5);
    EXPECT_LT(std::fabs(s.vy[0]), 1e-2);
}

TEST(EventSolverCollapse, ThreeDiskInelasticClusterReachesCommonVelocity) {
    // e = 0.05 is below the three-body collapse threshold 7 - 4 sqrt(3) (McNamara & Young,
    // Phys. Fluids A 4 (1992) 496): the disks end up moving together with the centre-of-mass
    // velocity (1.5 - 1) / 3 = 1/6 (up to the small relative motion the TC model leaves),
    // with momentum conserved to rounding throughout.
    Scene scene = box_scene(40, 4);
    scene.physics.restitution = 0.05;
    scene.backend_options["event"]["tc"] = "1e-9";  // small t_c: let the cluster nearly collapse
    SolverStats stats;
    const auto s = run_to(scene, make_state({{5, 2, 1.5, 0, 0.5, 1}, {6.5, 2, 0, 0, 0.5, 1}, {8, 2, -1, 0, 0.5, 1}}), 5,
                          &stats);
    EXPECT_NEAR(s.vx[0] + s.vx[1] + s.vx[2], 0.5, 1e-12);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(s.vx[i], 1.0 / 6.0, 1e-2) << "disk " << i;
    EXPECT_GT(stats.contacts, 10);
}

}  // namespace
}  // namespace collide
