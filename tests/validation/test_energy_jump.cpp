// Energy jumps attributed (validation/explain/energy_jump.h): the kind of contact from hand-made states
// whose contacts and energies are known, and the worked example of docs/stepping-rules.md
// ("Energy at e = 1") found by stepping the readable `step` rule; and the search of a recorded
// series for the interval the report has explained (largest_interval_jump).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/scene/scene_loader.h"
#include "reference/step_solver.h"
#include "validation/explain/energy_jump.h"
#include "validation/explain/explain_case.h"

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
    EXPECT_EQ(contact_kind(2, 1, 0, 0), "an isolated pair");
    EXPECT_EQ(contact_kind(3, 2, 0, 0), "3 disks in contact at once");
    EXPECT_EQ(contact_kind(1, 0, 1, 0), "a disk at a wall");
    EXPECT_EQ(contact_kind(1, 0, 2, 0), "a disk at 2 walls");
    EXPECT_EQ(contact_kind(1, 0, 0, 1), "a disk at a stone");
    EXPECT_EQ(contact_kind(2, 1, 1, 0), "a disk touching a wall and a disk");
    EXPECT_EQ(contact_kind(2, 1, 0, 1), "a disk touching a stone and a disk");
    EXPECT_EQ(contact_kind(4, 3, 1, 2), "4 disks in contact at once, with a wall and 2 stones");
    EXPECT_EQ(contact_kind(1, 0, 0, 0), "no contact found");
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
    EXPECT_DOUBLE_EQ(three[0].energy_change, -0.75 + 0.02);
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
    EXPECT_DOUBLE_EQ(groups[0].energy_change, 0.5 - 2.0);
    EXPECT_EQ(groups[1].kind, "an isolated pair");
    EXPECT_EQ(groups[1].energy_change, 0.0);
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
    EXPECT_EQ(groups[0].kind, "no contact found");
    EXPECT_EQ(groups[0].disks[0].index, 1u);
}

// A disk bouncing off a fixed stone: the stone takes the impulse without changing (inverse
// mass 0), so it is named as the contact, not the cause of a "no contact" group.
TEST(EnergyJump, StoneIsAContactPartner) {
    const Scene scene = box(20, Boundary::reflect);
    ParticleState<double> before, after;
    add(before, 10, 10, 1, 0);
    before.append_disk(11, 10, 0, 0, 0.5, 1, true);  // stone 1
    after = before;
    after.vx[0] = -0.5;  // e = 0.5 at the stone
    const auto groups = attribute_change(scene, before, after);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0].kind, "a disk at a stone");
    ASSERT_EQ(groups[0].stones.size(), 1u);
    EXPECT_EQ(groups[0].stones[0], std::make_pair(std::size_t{0}, std::size_t{1}));
}

// A contact seen in a sub-step: the pair is a little apart before and after the step, within
// what the disks travel in one dt.
TEST(EnergyJump, ContactWithinOneStepOfTravelCounts) {
    Scene scene = box(20, Boundary::reflect);
    scene.run.dt = 0.01;
    ParticleState<double> before, after;
    add(before, 10, 10, 1, 0), add(before, 11.015, 10, -1, 0);  // 0.015 apart, closing at 2 per time
    after = before;
    after.vx = {-1, 1};
    after.x = {9.99, 11.025};
    const auto groups = attribute_change(scene, before, after);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0].kind, "an isolated pair");
    // Farther apart than one step's travel: the two changes have nothing to do with each other.
    before.x[1] = after.x[1] = 11.5;
    EXPECT_EQ(attribute_change(scene, before, after).size(), 2u);
}

// A disk in a corner touches two walls: one group, "a disk at 2 walls".
TEST(EnergyJump, CornerIsTwoWalls) {
    const Scene scene = box(20, Boundary::reflect);
    ParticleState<double> before, after;
    add(before, 0.5, 0.5, -1, -1);
    after = before;
    after.vx = {1}, after.vy = {1};
    const auto groups = attribute_change(scene, before, after);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0].kind, "a disk at 2 walls");
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
    EXPECT_NEAR(jump.energy_change, -5.778, 5e-4);  // the figure the docs quote
    ASSERT_EQ(jump.groups.size(), 2u);
    const ContactGroup& g = jump.groups.front();
    EXPECT_EQ(g.kind, "3 disks in contact at once");
    ASSERT_EQ(g.disks.size(), 3u);
    EXPECT_EQ(g.disks[0].index, 72u);
    EXPECT_EQ(g.disks[1].index, 545u);
    EXPECT_EQ(g.disks[2].index, 839u);
    EXPECT_NEAR(g.energy_change, jump.energy_change, 1e-9);
    EXPECT_LT(g.energy_change, -0.1);  // far beyond rounding: a tenth of K/N (about 1 here) at least
    // The other group is the isolated pair 356-902, which keeps its energy (to rounding).
    const ContactGroup& pair = jump.groups[1];
    EXPECT_EQ(pair.kind, "an isolated pair");
    ASSERT_EQ(pair.disks.size(), 2u);
    EXPECT_EQ(pair.disks[0].index, 356u);
    EXPECT_EQ(pair.disks[1].index, 902u);
    EXPECT_NEAR(pair.energy_change, 0, 1e-12);
    EXPECT_NE(describe(jump).find("disk 72 touches 545 and 839"), std::string::npos);
}

// A state that turns non-finite is the answer, not a later finite step.
class BlowsUp : public Solver {
public:
    std::string name() const override { return "blows_up"; }
    void load(const Scene&, const ParticleState<double>& initial) override { state_ = initial; }
    void advance_to(double t) override {
        time_ = t;
        if (t > 0.0025) state_.vx[0] = std::nan("");
    }
    void read_state(ParticleState<double>& out) const override { out = state_; }
    double time() const override { return time_; }
    SolverStats stats() const override { return {}; }

private:
    ParticleState<double> state_;
    double time_ = 0;
};

TEST(EnergyJump, NonFiniteStateIsReported) {
    Scene scene = box(20, Boundary::reflect);
    scene.run.dt = 1e-3;
    ParticleState<double> initial;
    add(initial, 5, 5, 1, 0);
    BlowsUp solver;
    solver.load(scene, initial);
    const EnergyJump jump = largest_energy_change(solver, scene, 0.01);
    EXPECT_TRUE(jump.nonfinite);
    EXPECT_NEAR(jump.time_after, 0.003, 1e-12);
    EXPECT_NE(describe(jump).find("became non-finite"), std::string::npos);
}

TEST(EnergyJump, RefusesAnIntervalWithoutAWholeStep) {
    const Scene scene = load_scene(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/box_gas_1000.toml");
    StepSolver solver;
    solver.load(scene, generate_initial_state(scene));
    EXPECT_THROW(largest_energy_change(solver, scene, 0.0004), std::runtime_error);
}

// A recorded series with kinetic energies K(t) and no gravity (total = kinetic).
MetricSeries series_of(const std::vector<double>& kinetic) {
    MetricSeries s;
    for (std::size_t i = 0; i < kinetic.size(); ++i) {
        Metrics m;
        m.time = 0.5 * double(i);
        m.kinetic_energy = kinetic[i];
        s.push_back(m);
    }
    return s;
}

TEST(IntervalJump, TheLargestChangeStandsOutOfTheMedian) {
    // Changes per interval: +0.1, -0.2, -50 (at t = 1 -> 1.5), +0.1, relative to max K = 100.1.
    const auto jump = largest_interval_jump(series_of({100.0, 100.1, 99.9, 49.9, 50.0}));
    ASSERT_TRUE(jump.has_value());
    EXPECT_DOUBLE_EQ(jump->t0, 1.0);
    EXPECT_DOUBLE_EQ(jump->t1, 1.5);
    EXPECT_NEAR(jump->change, -50.0 / 100.1, 1e-12);
    EXPECT_DOUBLE_EQ(jump->scale, 100.1);
    // |changes| sorted: 0.001, 0.001, 0.002, 0.5 (over 100.1): the upper median is the third.
    EXPECT_NEAR(jump->median, 0.2 / 100.1, 1e-12);
}

TEST(IntervalJump, NoJumpBelowTheThresholdOrInsideTheNoise) {
    EXPECT_FALSE(largest_interval_jump(series_of({1.0, 1.0 + 5e-4, 1.0, 1.0 + 5e-4})).has_value());  // < 1e-3
    // Every interval changes by about as much: 0.02 is less than 10 x the median 0.01.
    EXPECT_FALSE(largest_interval_jump(series_of({1.0, 1.01, 1.02, 1.04, 1.05})).has_value());
    EXPECT_FALSE(largest_interval_jump(series_of({1.0, 2.0})).has_value());  // fewer than three points
    EXPECT_FALSE(largest_interval_jump(series_of({1.0, std::nan(""), 1.0, 1.0})).has_value());
}

TEST(IntervalJump, TheFirstOfEqualChangesIsTaken) {
    const auto jump = largest_interval_jump(series_of({1.0, 1.0, 0.5, 0.5, 0.0, 0.0, 0.0}));
    ASSERT_TRUE(jump.has_value());
    EXPECT_DOUBLE_EQ(jump->t0, 0.5);
}

}  // namespace
}  // namespace collide::validation
