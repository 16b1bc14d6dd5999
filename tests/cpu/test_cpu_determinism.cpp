// The `cpu` backend gives bitwise the same state for any thread count, across reruns, and
// with or without its specialised loops; and read_state undoes its internal reordering.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/numerics/state_hash.h"
#include "cpu/cpu_solver.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

// A busy scene that exercises every feature: gravity, damping, friction, e < 1, stones and
// two radii, in a reflecting or periodic box. 4500 disks: more than the size below which
// loops run inline (cpu/parallel_for.h), so several threads really share the work.
struct BusyCase {
    Scene scene;
    ParticleState<double> initial;
};

BusyCase busy_case(Boundary boundary) {
    BusyCase c;
    c.scene = test::box_scene(100, 100, boundary);
    c.scene.physics = Physics{0.4, 0.85, 0.1, 0.0, boundary == Boundary::periodic ? 0.0 : -2.0, 0.05};
    // Both rules: integrate-first in the closed box, collide-first in the periodic one.
    c.scene.run.dt = 4e-3;
    c.scene.run.substeps = 1;
    c.scene.run.order = boundary == Boundary::periodic ? StepOrder::collide_first : StepOrder::integrate_first;
    // Square lattice of spacing 1.25 with jitter, disks of radius 0.4 or 0.5 (no overlaps:
    // jitter 0.1 leaves a gap >= 0.05), every 50th a stone.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1), velocity(-3, 3);
    std::vector<test::DiskSpec> disks;
    for (int k = 0; k < 4500; ++k) {
        const double x = 1.0 + 1.25 * (k % 78) + jitter(rng), y = 1.0 + 1.25 * (k / 78) + jitter(rng);
        disks.push_back({x, y, velocity(rng), velocity(rng), k % 3 == 0 ? 0.4 : 0.5, 1.0 + (k % 5), k % 50 == 0});
    }
    c.initial = test::make_state(disks);
    return c;
}

std::uint64_t hash_after_200_steps(const BusyCase& c, int threads, BackendOptions options = {}) {
    options.threads = threads;
    cpu::CpuSolver solver(options);
    solver.load(c.scene, c.initial);
    for (int k = 0; k < 200; ++k) solver.step();
    EXPECT_GT(solver.stats().contacts, 1000) << "the scene should be busy";
    ParticleState<double> s;
    solver.read_state(s);
    return state_hash(s);
}

class CpuDeterminism : public ::testing::TestWithParam<Boundary> {};

TEST_P(CpuDeterminism, SameStateForOneTwoAndEightThreadsAndReruns) {
    const BusyCase c = busy_case(GetParam());
    const std::uint64_t one = hash_after_200_steps(c, 1);
    EXPECT_EQ(hash_after_200_steps(c, 2), one);
    EXPECT_EQ(hash_after_200_steps(c, 8), one);
    EXPECT_EQ(hash_after_200_steps(c, 2), one) << "rerun";
}

TEST_P(CpuDeterminism, SpecialisedAndGenericLoopsAgreeBitwise) {
    // Gravity off, friction off, one radius, no stones: every specialisation is active.
    BusyCase c = busy_case(GetParam());
    c.scene.physics.gravity_y = 0;
    c.scene.physics.friction = 0;
    c.scene.physics.damping = 0;
    for (std::size_t i = 0; i < c.initial.size(); ++i) {
        c.initial.radius[i] = 0.5;
        c.initial.inv_mass[i] = 1.0 / c.initial.mass[i];
    }
    EXPECT_EQ(hash_after_200_steps(c, 2, {0, "", "", {{"specialise", "off"}}}), hash_after_200_steps(c, 2));
}

TEST_P(CpuDeterminism, SameStateForAnyThreadCountWithoutEveryStepReorder) {
    // sort_interval 0: the search reads through the cell list's index; 3: both paths. Each on
    // the pair list (the default) and on the cell path (skin 0).
    const BusyCase c = busy_case(GetParam());
    for (const char* skin : {"0.5", "0"})
        for (const char* k : {"0", "3"}) {
            const BackendOptions options{0, "", "", {{"sort_interval", k}, {"skin", skin}}};
            const std::uint64_t one = hash_after_200_steps(c, 1, options);
            EXPECT_EQ(hash_after_200_steps(c, 2, options), one) << "sort_interval " << k << ", skin " << skin;
            EXPECT_EQ(hash_after_200_steps(c, 8, options), one) << "sort_interval " << k << ", skin " << skin;
        }
}

TEST_P(CpuDeterminism, CellPathSameStateForAnyThreadCount) {
    const BusyCase c = busy_case(GetParam());
    const BackendOptions cells{0, "", "", {{"skin", "0"}}};
    const std::uint64_t one = hash_after_200_steps(c, 1, cells);
    EXPECT_EQ(hash_after_200_steps(c, 2, cells), one);
    EXPECT_EQ(hash_after_200_steps(c, 8, cells), one);
}

// The two searches add a disk's contacts in different orders. Float addition is commutative
// but not associative, so the bits part only where a disk has three or more contacts at once
// (the pile of the reflecting case), and the option must really switch the search.
TEST(CpuSolver, SkinChoosesTheSearch) {
    const BusyCase c = busy_case(Boundary::reflect);
    for (const char* skin : {"0.5", "0"}) {
        cpu::CpuSolver solver({1, "", "", {{"skin", skin}}});
        solver.load(c.scene, c.initial);
        for (int k = 0; k < 50; ++k) solver.step();
        const auto counters = solver.stats().counters;
        const bool listed = counters.count("pair_list_builds") > 0;
        EXPECT_EQ(listed, std::string(skin) != "0") << "skin " << skin;
        if (listed) {
            EXPECT_GE(counters.at("pair_list_builds"), 1.0);
            EXPECT_LT(counters.at("pair_list_builds"), 50.0) << "a list that never outlives a step buys nothing";
        }
        EXPECT_EQ(solver.provenance().at("cpu.skin"), skin);
    }
}

INSTANTIATE_TEST_SUITE_P(Boundaries, CpuDeterminism, ::testing::Values(Boundary::reflect, Boundary::periodic),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(CpuSolver, ReadStateReturnsTheScenesOrderAfterReordering) {
    const BusyCase c = busy_case(Boundary::reflect);
    cpu::CpuSolver solver({1, "", "", {{"sort_interval", "1"}}});
    solver.load(c.scene, c.initial);
    for (int k = 0; k < 20; ++k) solver.step();
    ParticleState<double> s;
    solver.read_state(s);
    // Radius, mass and stone flag travel with each disk: they must be back in scene order.
    for (std::size_t i = 0; i < s.size(); ++i) {
        ASSERT_EQ(s.radius[i], double(float(c.initial.radius[i]))) << "disk " << i;
        ASSERT_EQ(s.mass[i], double(float(c.initial.mass[i]))) << "disk " << i;
        ASSERT_EQ(s.inv_mass[i] == 0, c.initial.inv_mass[i] == 0) << "disk " << i;
        if (c.initial.inv_mass[i] == 0) {  // stones never move: exact positions
            ASSERT_EQ(s.x[i], double(float(c.initial.x[i])));
            ASSERT_EQ(s.y[i], double(float(c.initial.y[i])));
        }
    }
}

TEST(CpuSolver, RejectsUnknownSettingsWithTheirName) {
    try {
        cpu::CpuSolver solver({0, "", "", {{"sort_intervall", "4"}}});
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("sort_intervall"), std::string::npos) << e.what();
    }
    EXPECT_THROW(cpu::CpuSolver({0, "", "", {{"sort_interval", "-1"}}}), std::invalid_argument);
    // The scene's [backend.cpu] table is checked when the scene is loaded.
    Scene scene = test::box_scene(10, 10);
    scene.backend_options["cpu"]["sort_interval"] = "often";
    cpu::CpuSolver solver({});
    try {
        solver.load(scene, test::make_state({{5, 5, 0, 0, 0.5, 1}}));
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("[backend.cpu]"), std::string::npos) << e.what();
    }
    EXPECT_THROW(cpu::CpuSolver({0, "", "", {{"specialise", "yes"}}}), std::invalid_argument);
    EXPECT_THROW(cpu::CpuSolver({0, "", "", {{"skin", "-0.1"}}}), std::invalid_argument);
    EXPECT_THROW(cpu::CpuSolver({0, "", "", {{"skin", "wide"}}}), std::invalid_argument);
}

}  // namespace
}  // namespace collide
