// The one kinetic temperature (core/thermo/kinetic_temperature.h) and the finite-N pressure
// estimator (core/thermo/pressure_estimator.h) on states whose values follow by hand.
#include <gtest/gtest.h>

#include "core/thermo/kinetic_temperature.h"
#include "core/thermo/pressure_estimator.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

Scene periodic_box() {
    Scene s = test::box_scene(10, 10);
    s.world.boundary = Boundary::periodic;
    return s;
}

TEST(KineticTemperature, PeriodicBoxCountsHeatInTheCentreOfMassFrame) {
    // Two unit masses at vx = 1 and 3: K = 5, P = 4, M = 2, K_int = 5 - 16 / 4 = 1, N - 1 = 1.
    const auto state = test::make_state({{1, 1, 1, 0, 0.5, 1}, {5, 5, 3, 0, 0.5, 1}});
    const KineticTemperature t = kinetic_temperature(periodic_box(), state);
    EXPECT_DOUBLE_EQ(t.kinetic_energy, 5);
    EXPECT_DOUBLE_EQ(t.internal_kinetic_energy, 1);
    EXPECT_EQ(t.degrees_of_freedom, 1);
    EXPECT_DOUBLE_EQ(t.kT(), 1);
}

TEST(KineticTemperature, WalledBoxCountsTheWholeEnergyOverN) {
    const auto state = test::make_state({{1, 1, 1, 0, 0.5, 1}, {5, 5, 3, 0, 0.5, 1}});
    const KineticTemperature t = kinetic_temperature(test::box_scene(10, 10), state);
    EXPECT_DOUBLE_EQ(t.internal_kinetic_energy, 5);
    EXPECT_DOUBLE_EQ(t.kT(), 2.5);
}

TEST(KineticTemperature, MovingTheCentreOfMassChangesNothingInAPeriodicBox) {
    auto state = test::make_state({{1, 1, 0.3, -1.2, 0.5, 2}, {5, 5, -0.7, 0.4, 0.5, 1}, {8, 2, 0.1, 0.9, 0.5, 3}});
    const double before = kinetic_temperature(periodic_box(), state).kT();
    for (std::size_t i = 0; i < state.size(); ++i) state.vx[i] += 4.0, state.vy[i] -= 2.5;
    EXPECT_NEAR(kinetic_temperature(periodic_box(), state).kT(), before, 1e-13);
}

TEST(KineticTemperature, StonesAreLeftOut) {
    const auto state = test::make_state({{1, 1, 1, 0, 0.5, 1}, {5, 5, 3, 0, 0.5, 1}, {8, 8, 9, 9, 0.5, 1, true}});
    const KineticTemperature t = kinetic_temperature(periodic_box(), state);
    EXPECT_EQ(t.moving_disks, 2u);
    EXPECT_DOUBLE_EQ(t.kT(), 1);
}

TEST(PressureEstimator, FiniteNFactorIsNMinusOneOverN) {
    // N = 4 in a periodic box: Z = 1 + (3/4) W / K_int.
    KineticTemperature t = kinetic_temperature(8.0, 0, 0, 4.0, 4, true);
    EXPECT_DOUBLE_EQ(compressibility_factor(2.0, t), 1 + 0.75 * 2.0 / 8.0);
    t = kinetic_temperature(8.0, 0, 0, 4.0, 4, false);  // walls: factor 1
    EXPECT_DOUBLE_EQ(compressibility_factor(2.0, t), 1 + 2.0 / 8.0);
    // beta P d^2 = Z (N / A) d^2.
    EXPECT_DOUBLE_EQ(beta_pressure_d2(2.0, 4, 16.0, 1.5), 2.0 * 0.25 * 2.25);
}

}  // namespace
}  // namespace collide
