// The integrate-first rule on cases with exact answers, run on every stepped
// backend that implements the shared contact law (`step` in double, `cpu` in float).
// Expected values come from the contact law's physics (physics/contact_law.cl.h): for an impact
// with normal n and relative velocity u = v_1 - v_2, u_n = u.n < 0,
//     normal:     u_n' = -e u_n                                  (Newton's restitution law)
//     tangential: |u_t'| = |u_t| - min(mu (1 + e) |u_n|, |u_t|)  (Coulomb, capped at sticking)
// with u_t' parallel to u_t: friction slows sliding and can stop it, never reverse it.
#include <gtest/gtest.h>

#include <cmath>

#include "core/backend_registry.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

class IntegrateFirstRule : public ::testing::TestWithParam<std::string> {
protected:
    std::unique_ptr<Solver> make() const { return find_backend(GetParam()).create(BackendOptions{}); }
    // Float backends resolve one impact to a few float roundings of O(1) quantities.
    double tolerance() const { return find_backend(GetParam()).precision == "double" ? 1e-12 : 1e-5; }
};

Scene rule_scene(double restitution, double friction) {
    Scene scene = test::box_scene(20, 20);
    scene.physics.restitution = restitution;
    scene.physics.friction = friction;
    scene.run.order = StepOrder::integrate_first;
    scene.run.dt = 4e-3;
    scene.run.substeps = 4;
    return scene;
}

TEST_P(IntegrateFirstRule, RestitutionGivesTheNormalSpeedOfAnIsolatedHeadOnPair) {
    for (double e : {0.0, 0.4, 1.0}) {
        const Scene scene = rule_scene(e, 0.0);
        // Masses 1 and 3 approach at relative speed 2; contact after 0.25 s.
        const auto initial = test::make_state({{9, 10, 1.5, 0, 0.5, 1}, {10.5, 10, -0.5, 0, 0.5, 3}});
        auto solver = make();
        solver->load(scene, initial);
        solver->advance_to(1.0);
        ParticleState<double> s;
        solver->read_state(s);
        // Along n = -x (from disk 2 to disk 1) u_n = -2, so u_n' = -e u_n gives
        // v_1' - v_2' = -2 e; momentum 1.5 - 1.5 = 0 is conserved: v_1' + 3 v_2' = 0.
        // Hence v_1' = -3 e / 2 and v_2' = e / 2.
        EXPECT_NEAR(s.vx[0] - s.vx[1], -2 * e, tolerance()) << "e = " << e;
        EXPECT_NEAR(s.vx[0], -1.5 * e, tolerance()) << "e = " << e;
        EXPECT_NEAR(s.vx[1], 0.5 * e, tolerance()) << "e = " << e;
        EXPECT_EQ(s.vy[0], 0.0);
    }
}

// Runs an oblique impact one step at a time. On the step where the velocities change,
// the contact normal is the one of the positions after that sub-step's drift (no forces:
// x + v h), which the test recomputes to decompose u before and after.
struct Impact {
    double un_before, ut_before, un_after, ut_after_along;  // ut_after_along: u_t'.t_hat
    double ut_after_across;                                 // the rest of u_t' (should be 0)
};

Impact oblique_impact(Solver& solver, const Scene& scene) {
    // Disk 1 moves right and up; disk 2 left and down; their centres are offset in y.
    const auto initial = test::make_state({{8, 10, 1, 0.6, 0.5, 1}, {10, 10.3, -1, -0.6, 0.5, 2}});
    solver.load(scene, initial);
    ParticleState<double> before, after;
    solver.read_state(before);
    const double h = scene.run.dt;  // one sub-step per step in this test
    for (int k = 1; k < 1000; ++k) {
        solver.advance_to(k * h);
        solver.read_state(after);
        if (after.vx[0] != before.vx[0]) {
            const double dx = (before.x[0] + before.vx[0] * h) - (before.x[1] + before.vx[1] * h);
            const double dy = (before.y[0] + before.vy[0] * h) - (before.y[1] + before.vy[1] * h);
            const double d = std::hypot(dx, dy), nx = dx / d, ny = dy / d;
            const double ux = before.vx[0] - before.vx[1], uy = before.vy[0] - before.vy[1];
            const double wx = after.vx[0] - after.vx[1], wy = after.vy[0] - after.vy[1];
            const double un = ux * nx + uy * ny, wn = wx * nx + wy * ny;
            const double tx = ux - un * nx, ty = uy - un * ny, ut = std::hypot(tx, ty);
            const double wtx = wx - wn * nx, wty = wy - wn * ny;
            return {un, ut, wn, (wtx * tx + wty * ty) / ut, (wtx * -ty + wty * tx) / ut};
        }
        before = after;
    }
    ADD_FAILURE() << "no impact";
    return {};
}

TEST_P(IntegrateFirstRule, FrictionReducesTangentialSlidingAndNeverReversesIt) {
    for (double mu : {0.0, 0.1, 0.3, 10.0}) {
        const double e = 0.4;
        Scene scene = rule_scene(e, mu);
        scene.run.substeps = 1;
        auto solver = make();
        const Impact i = oblique_impact(*solver, scene);
        ASSERT_LT(i.un_before, 0.0);
        ASSERT_GT(i.ut_before, 0.1) << "the impact should be oblique";
        const double expected_ut = i.ut_before - std::min(mu * (1 + e) * -i.un_before, i.ut_before);
        // Rounding of float positions tilts the recomputed normal by ~1e-6 rad.
        const double tol = tolerance() * 10;
        EXPECT_NEAR(i.un_after, -e * i.un_before, tol) << "mu = " << mu;
        EXPECT_NEAR(i.ut_after_along, expected_ut, tol) << "mu = " << mu;
        EXPECT_GE(i.ut_after_along, -tol) << "friction reversed the sliding, mu = " << mu;
        EXPECT_NEAR(i.ut_after_across, 0.0, tol);
        if (mu > 0) {
            EXPECT_LT(i.ut_after_along, i.ut_before) << "friction must slow the sliding";
        }
    }
}

TEST_P(IntegrateFirstRule, StonesStayPutUnderALoad) {
    // A floor of 10 touching stones across a box 10 wide carries a pile of 30 disks falling
    // under gravity with a granular material (e = 0.4, mu = 0.1) for 3 s.
    Scene scene = rule_scene(0.4, 0.1);
    scene.world = World{0, 0, 10, 20, Boundary::reflect};
    scene.physics.gravity_y = -9.81;
    scene.physics.wall_restitution = 0.85;
    scene.run.dt = 1.0 / 60;
    std::vector<test::DiskSpec> disks;
    for (int k = 0; k < 10; ++k) disks.push_back({0.5 + k, 3, 0, 0, 0.5, 1, true});
    for (int k = 0; k < 30; ++k) disks.push_back({1.0 + (k % 8) * 1.1, 4.5 + (k / 8) * 1.1, 0, 0, 0.45, 1});
    const auto initial = test::make_state(disks);
    auto solver = make();
    solver->load(scene, initial);
    solver->advance_to(3.0);
    ParticleState<double> s;
    solver->read_state(s);
    for (int k = 0; k < 10; ++k) {
        EXPECT_EQ(s.x[k], initial.x[k]) << "stone " << k;
        EXPECT_EQ(s.y[k], initial.y[k]) << "stone " << k;
        EXPECT_EQ(s.vx[k], 0.0);
        EXPECT_EQ(s.vy[k], 0.0);
    }
    // The load really rests on the stones: no disk centre has passed the floor's top
    // (y = 3.5), and some of the pile has come to rest on it. (One Jacobi projection per
    // sub-step leaves a load-dependent overlap in a pile, about a third of a radius in the
    // bottom layer here; that is the rule's known softness, not a stone that moved.)
    int resting = 0;
    for (std::size_t i = 10; i < s.size(); ++i) {
        EXPECT_GT(s.y[i], 3.5) << "disk " << i << " sank through the stones";
        if (s.y[i] < 20 && std::hypot(s.vx[i], s.vy[i]) < 0.5) ++resting;
    }
    EXPECT_GT(resting, 0);
}

std::vector<std::string> stepped_backends() {
    std::vector<std::string> names;
    for (const auto& b : all_backends())
        if (b.name == "step" || b.name == "cpu") names.push_back(b.name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(SteppedBackends, IntegrateFirstRule, ::testing::ValuesIn(stepped_backends()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace collide
