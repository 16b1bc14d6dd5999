// psi6 of exact lattices (|psi6| = 1, the phase turns by 6 alpha with the lattice) and the
// traversal count of phase series whose traversals are known.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/structure/orientational_order.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

constexpr double pi = std::numbers::pi;

// A hexagonal lattice of `columns` x `rows` disks of diameter 1 at spacing a, turned by alpha
// about the origin and moved by (x0, y0).
ParticleState<double> hexagonal_lattice(int columns, int rows, double a, double alpha, double x0, double y0) {
    std::vector<test::DiskSpec> disks;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const double x = (column + 0.5 * (row % 2)) * a, y = row * a * std::sqrt(3.0) / 2;
            disks.push_back({x0 + x * std::cos(alpha) - y * std::sin(alpha),
                             y0 + x * std::sin(alpha) + y * std::cos(alpha), 0, 0, 0.5, 1});
        }
    return test::make_state(disks);
}

// A periodic box that the lattice fills: every disk has six neighbours at distance a.
TEST(OrientationalOrder, PeriodicHexagonalLatticeHasUnitPsi6) {
    const double a = 1.1;
    const Scene scene = test::box_scene(12 * a, 10 * a * std::sqrt(3.0) / 2, Boundary::periodic);
    const auto psi6 = global_psi6(scene.world, hexagonal_lattice(12, 10, a, 0, 0.2, 0.3));
    EXPECT_NEAR(std::abs(psi6), 1.0, 1e-12);
    EXPECT_NEAR(std::arg(psi6), 0.0, 1e-12);
}

// A patch of lattice inside walls: edge disks have fewer neighbours, but each bond is still
// at a multiple of 60 degrees plus alpha, so psi6 = exp(6 i alpha) exactly.
TEST(OrientationalOrder, TurningTheLatticeTurnsThePhaseSixTimes) {
    const Scene scene = test::box_scene(40, 40);
    for (double alpha : {0.0, 0.05, 0.2, -0.3}) {
        const auto psi6 = global_psi6(scene.world, hexagonal_lattice(8, 8, 1.1, alpha, 20, 12));
        EXPECT_NEAR(std::abs(psi6), 1.0, 1e-12) << alpha;
        EXPECT_NEAR(std::remainder(std::arg(psi6) - 6 * alpha, 2 * pi), 0.0, 1e-12) << alpha;
    }
}

// A gas without order: |psi6| of order 1 / sqrt(N), far from 1.
TEST(OrientationalOrder, RandomGasHasLittleOrder) {
    const Scene scene = test::box_scene(40, 40, Boundary::periodic);
    EXPECT_LT(std::abs(global_psi6(scene.world, test::random_gas(scene, 800, 0.5, 7))), 0.15);
}

// Phases of a phase that advances by `step` per sample, `samples` times, wrapped into (-pi, pi].
std::vector<double> ramp(double start, double step, int samples) {
    std::vector<double> phases;
    for (int k = 0; k < samples; ++k) phases.push_back(std::remainder(start + k * step, 2 * pi));
    return phases;
}

TEST(OrientationalOrder, SteadyRotationTraversesOnceEachTurn) {
    EXPECT_EQ(phase_traversals(ramp(0.3, 0.1, int(3.5 * 2 * pi / 0.1))), 3u);   // 3.5 turns
    EXPECT_EQ(phase_traversals(ramp(-2.0, -0.1, int(2.9 * 2 * pi / 0.1))), 2u); // 2.9 turns backwards
    EXPECT_EQ(phase_traversals(ramp(1.0, 0.1, int(0.95 * 2 * pi / 0.1))), 0u);  // not yet a full turn
}

// Back and forth over 1.8 pi never covers the range however long it goes; over 2.2 pi it
// covers it on every swing after the first (the first starts from the middle).
TEST(OrientationalOrder, SwingsCountOnlyWhenTheyCoverTheRange) {
    auto swings = [](double amplitude, int periods) {
        std::vector<double> phases;
        for (int k = 0; k < periods * 200; ++k)
            phases.push_back(std::remainder(amplitude * std::sin(2 * pi * k / 200.0), 2 * pi));
        return phases;
    };
    EXPECT_EQ(phase_traversals(swings(0.9 * pi, 20)), 0u);
    const std::size_t swept = phase_traversals(swings(1.1 * pi, 5));
    EXPECT_GE(swept, 8u);
    EXPECT_LE(swept, 10u);
}

TEST(OrientationalOrder, MixedFromThreeTraversals) {
    EXPECT_FALSE(phase_mixed(2));
    EXPECT_TRUE(phase_mixed(3));
    EXPECT_EQ(phase_traversals({}), 0u);
    EXPECT_EQ(phase_traversals({1.0}), 0u);
}

}  // namespace
}  // namespace collide
