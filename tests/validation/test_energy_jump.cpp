// Energy jumps attributed (validation/energy_jump.h): the kind of contact from hand-made states
// whose contacts and energies are known, and the worked example of docs/stepping-rules.md
// ("Energy at e = 1") found by stepping the readable `step` rule.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/scene_loader.h"
#include "reference/step_solver.h"
#include "validation/energy_jump.h"

namespace collide::validation {
namespace {

Scene box(double size, Boundary boundary) {
    Scene s;
    s.world = {0, 0, size, size, boundary};
    return s;
}

void add(ParticleState<double>& p, double x, double y, double vx, double vy, double r = 0.5, double m = 1) {
    p.append_disk(x, y, vx, vy, r, m, false);
}

TEST(EnergyJump, KindsInWords) {
    EXPECT_EQ(contact_kind(2, 1, 0), "an isolated pair");
    EXPECT_EQ(contact_kind(3, 2, 0), "3 disks in contact at once");
    EXPECT_EQ(contact_kind(1, 0, 1), "a disk at a wall");
    EXPECT_EQ(contact_kind(2, 1, 1), "a disk touching a wall and a disk");
    EXPECT_EQ(contact_kind(4, 3, 1), "4 disks and a wall");
    EXPECT_EQ(contact_kind(1, 0, 0), "no contact (a force or damping)");
}

// Three unit-mass disks in a row, touching: the middle one takes two impulses at once and the
// three lose energy; a fourth disk far away flies free and is no part of the change.
TEST(EnergyJump, ThreeDisksInContactAreOneGroup) {
    const Scene scene = box(20, Boundary::reflect);
    ParticleState<double> before, after;
    add(before, 5, 10, 1, 0), add(before, 6, 10, 0, 0), add(before, 7, 10, -1, 0), add(before, 15, 15, 0.3, 0.4);
    after = before;
    after.vx = {-0.5, 0.2, 0.5, 0.3};  // K: 0.5 + 0 + 0.5 -> 0.125 + 0.02 + 0.125
    const auto three = attribute_change(scene, before, after);
    ASSERT_EQ(three.size(), 1u);
    EXPECT_EQ(three[0].kind, "3 disks in contact at once");
    ASSERT_EQ(three[0].pairs.size(), 2u);
    EXPECT_EQ(three[0].pairs[0], std::make_pair(std::size_t{0}, std::size_t{1}));
    EXPECT_EQ(three[0].pairs[1], std::make_pair(std::size_t{1}, std::size_t{2}));
    EXPECT_DOUBLE_EQ(three[0].kinetic_change, -0.75 + 0.02);
}

// An elastic head-on exchange between equal masses swaps the velocities: each disk keeps its
// K, yet both are part of the step's contacts (a group with change zero);
// the larger change of a disk bouncing off the left wall with e = 0.5 comes first.
TEST(EnergyJump, PairAndWallGroupsOrderedByChange) {
    const Scene scene = box(20, Boundary::reflect);
    ParticleState<double> before, after;
    add(before, 10, 10, 1, 0), add(before, 11, 10, -1, 0), add(before, 0.5, 5, -2, 0);
    after = before;
    after.vx = {-1, 1, 1};  // the pair swaps; the wall disk returns at half speed
    const auto groups = attribute_change(scene, before, after);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].kind, "a disk at a wall");
    ASSERT_EQ(groups[0].walls.size(), 1u);
    EXPECT_EQ(groups[0].walls[0].second, "left");
    EXPECT_DOUBLE_EQ(groups[0].kinetic_change, 0.5 - 2.0);
    EXPECT_EQ(groups[1].kind, "an isolated pair");
    EXPECT_EQ(groups[1].kinetic_change, 0.0);
}

// Under gravity every disk's velocity changes by g dt each step; only a contact's change counts.
TEST(EnergyJump, GravityAloneIsNoContact) {
    Scene scene = box(20, Boundary::reflect);
    scene.physics.gravity_y = -9.81;
    scene.run.dt = 1e-3;
    ParticleState<double> before, after;
    add(before, 5, 10, 1, 0), add(before, 15, 15, 0, 2);
    after = before;
    for (std::size_t i = 0; i < 2; ++i) after.vy[i] += -9.81 * 1e-3;
    EXPECT_TRUE(attribute_change(scene, before, after).empty());
    after.vx[1] = 0.5;  // a kick gravity does not explain
    const auto groups = attribute_change(scene, before, after);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0].kind, "no contact (a force or damping)");
    EXPECT_EQ(groups[0].disks[0].index, 1u);
}

// In a periodic box a pair touches across the boundary (nearest image); nothing is a wall.
TEST(EnergyJump, PeriodicPairAcrossTheBoundary) {
    const Scene scene = box(10, Boundary::periodic);
    ParticleState<double> before, after;
    add(before, 0.4, 5, -1, 0), add(before, 9.7, 5, 0, 0);  // 0.7 apart through x = 0
    after = before;
    after.vx = {-0.2, -0.5};
    const auto groups = attribute_change(scene, before, after);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0].kind, "an isolated pair");
    EXPECT_TRUE(groups[0].walls.empty());
}

// docs/stepping-rules.md, "Energy at e = 1": in box_gas_1000 (step, seed 1, dt = 1e-3) the step
// that changes K most up to t = 1.1 is one where disk 72 takes impulses from 545 and 839 at once.
// Physics says any isolated pair of that step keeps its energy (to rounding).
TEST(EnergyJump, WorkedExampleOfTheSteppingRulesPage) {
    const Scene scene = load_scene(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/box_gas_1000.toml");
    StepSolver solver;
    solver.load(scene, generate_initial_state(scene));
    const EnergyJump jump = largest_energy_change(solver, scene, 1.1);
    std::printf("%s\n", describe(jump).c_str());
    EXPECT_NEAR(jump.time_after, 1.036, 1e-12);
    ASSERT_FALSE(jump.groups.empty());
    const ContactGroup& g = jump.groups.front();
    EXPECT_EQ(g.kind, "3 disks in contact at once");
    ASSERT_EQ(g.disks.size(), 3u);
    EXPECT_EQ(g.disks[0].index, 72u);
    EXPECT_EQ(g.disks[1].index, 545u);
    EXPECT_EQ(g.disks[2].index, 839u);
    EXPECT_NEAR(g.kinetic_change, jump.kinetic_change, 1e-9);
    EXPECT_LT(g.kinetic_change, -0.1);  // far beyond rounding: a tenth of K/N (about 1 here) at least
    for (std::size_t k = 1; k < jump.groups.size(); ++k)
        if (jump.groups[k].kind == "an isolated pair") {
            EXPECT_NEAR(jump.groups[k].kinetic_change, 0, 1e-12);
        }
    EXPECT_NE(describe(jump).find("disk 72 touches 545 and 839"), std::string::npos);
}

TEST(EnergyJump, RefusesAnIntervalWithoutAWholeStep) {
    const Scene scene = load_scene(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/box_gas_1000.toml");
    StepSolver solver;
    solver.load(scene, generate_initial_state(scene));
    EXPECT_THROW(largest_energy_change(solver, scene, 0.0004), std::runtime_error);
}

}  // namespace
}  // namespace collide::validation
