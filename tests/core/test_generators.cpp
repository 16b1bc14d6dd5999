// The seeded generators: counts, regions, no overlaps, the statistics of the velocity and
// radius distributions against their analytic moments, lattice geometry, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/scene/gas_scene.h"
#include "core/metrics.h"
#include "core/scene/scene_loader.h"
#include "core/numerics/state_hash.h"
#include "core/thermo/kinetic_temperature.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

constexpr double pi = 3.14159265358979323846;

ParticleGenerator gas_block(std::int64_t count, double radius, double mass) {
    ParticleGenerator g;
    g.kind = "gas";
    g.count = count;
    g.radius = radius;
    g.mass = mass;
    return g;
}

Scene scene_with(double width, double height, std::vector<ParticleGenerator> blocks,
                 Boundary boundary = Boundary::reflect, std::uint64_t seed = 7) {
    Scene s = test::box_scene(width, height, boundary);
    s.seed = seed;
    s.generators = std::move(blocks);
    return s;
}

TEST(GasGenerator, PlacesCountDisksInsideTheRegionWithoutOverlaps) {
    // 375 disks of radius 0.4 in a 30 x 30 region: phi = 375 pi 0.16 / 900 = 0.21.
    ParticleGenerator g = gas_block(375, 0.4, 1.0);
    g.region = std::array<double, 4>{10, 5, 40, 35};
    const Scene scene = scene_with(50, 40, {g});
    const auto s = generate_initial_state(scene);
    ASSERT_EQ(s.size(), 375u);
    for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_GE(s.x[i] - s.radius[i], 10.0);
        EXPECT_LE(s.x[i] + s.radius[i], 40.0);
        EXPECT_GE(s.y[i] - s.radius[i], 5.0);
        EXPECT_LE(s.y[i] + s.radius[i], 35.0);
        EXPECT_EQ(s.mass[i], 1.0);
        EXPECT_EQ(s.inv_mass[i], 1.0);
    }
    EXPECT_EQ(test::brute_force_overlapping_pairs(scene, s), 0);
}

TEST(GasGenerator, PeriodicGasUsesTheWholeBoxWithMinimumImages) {
    // phi = 2000 pi 0.25 / 3600 = 0.44: dense enough that disks straddle the wrap.
    const Scene scene = scene_with(60, 60, {gas_block(2000, 0.5, 1.0)}, Boundary::periodic);
    const auto s = generate_initial_state(scene);
    ASSERT_EQ(s.size(), 2000u);
    bool straddles = false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_TRUE(s.x[i] >= 0 && s.x[i] < 60 && s.y[i] >= 0 && s.y[i] < 60);
        straddles = straddles || s.x[i] < 0.5 || s.x[i] > 59.5;
    }
    EXPECT_TRUE(straddles);
    EXPECT_EQ(test::brute_force_overlapping_pairs(scene, s), 0);
}

TEST(GasGenerator, MaxwellGasHasItsTemperatureWithinTheStandardError) {
    // 2D equipartition: <m |v|^2 / 2> = kT. The sample T = sum m |v|^2 / (2N) averages 2N
    // terms m v_c^2 / kT ~ chi^2_1 (variance 2), so its standard error is kT / sqrt(N).
    const double kT = 1.5, m = 2.0;
    const std::int64_t n = 20000;
    ParticleGenerator g = gas_block(n, 0.5, m);
    g.velocity_kind = "maxwell";
    g.temperature = kT;
    const Scene scene = scene_with(300, 300, {g});
    const auto s = generate_initial_state(scene);
    double twice_kinetic = 0, px = 0, py = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        twice_kinetic += m * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
        px += s.vx[i];
        py += s.vy[i];
    }
    const double temperature = twice_kinetic / (2.0 * double(n));
    EXPECT_NEAR(temperature, kT, 4 * kT / std::sqrt(double(n)));
    // Mean velocity component: 0 with standard error sqrt(kT/m) / sqrt(N).
    EXPECT_NEAR(px / double(n), 0.0, 4 * std::sqrt(kT / m / double(n)));
    EXPECT_NEAR(py / double(n), 0.0, 4 * std::sqrt(kT / m / double(n)));
}

// A Maxwell draw in a periodic box leaves the centre of mass at rest (docs/scenes.md,
// `velocity`): the total momentum is 0 to rounding, against a raw draw's sqrt(N m kT) ~ 20.
// Walls keep the raw draw; `drift = "raw"` keeps it in a periodic box too.
std::array<double, 2> total_momentum(const ParticleState<double>& s) {
    double px = 0, py = 0;
    for (std::size_t i = 0; i < s.size(); ++i) px += s.mass[i] * s.vx[i], py += s.mass[i] * s.vy[i];
    return {px, py};
}

ParticleGenerator maxwell_block(double kT) {
    ParticleGenerator g = gas_block(400, 0.5, 2.0);
    g.velocity_kind = "maxwell";
    g.temperature = kT;
    return g;
}

TEST(GasGenerator, PeriodicMaxwellDrawHasNoTotalMomentumAndWallsKeepTheRawDraw) {
    const auto periodic = generate_initial_state(scene_with(60, 60, {maxwell_block(1.5)}, Boundary::periodic));
    const auto [px, py] = total_momentum(periodic);
    EXPECT_NEAR(px, 0.0, 1e-12);
    EXPECT_NEAR(py, 0.0, 1e-12);

    ParticleGenerator raw = maxwell_block(1.5);
    raw.drift = "raw";
    const auto kept = total_momentum(generate_initial_state(scene_with(60, 60, {raw}, Boundary::periodic)));
    const auto walls = total_momentum(generate_initial_state(scene_with(60, 60, {maxwell_block(1.5)})));
    EXPECT_GT(std::hypot(kept[0], kept[1]), 1e-3) << "the raw draw has a momentum of order sqrt(N m kT)";
    EXPECT_EQ(kept, walls) << "the same draw, left as drawn";
}

// `exact = true`: the kinetic temperature of the block (core/thermo/kinetic_temperature.h) is kT
// to rounding: K / (N - 1) with the drift removed, K / N with walls.
TEST(GasGenerator, ExactTemperatureRescalesToKTOnTheDegreesOfFreedomOfTheBox) {
    ParticleGenerator g = maxwell_block(1.5);
    g.exact_temperature = true;
    for (Boundary boundary : {Boundary::periodic, Boundary::reflect}) {
        const Scene scene = scene_with(60, 60, {g}, boundary);
        const KineticTemperature t = kinetic_temperature(scene, generate_initial_state(scene));
        EXPECT_NEAR(t.kT(), 1.5, 1e-12);
        EXPECT_EQ(t.degrees_of_freedom, boundary == Boundary::periodic ? 399 : 400);
        EXPECT_NEAR(t.internal_kinetic_energy, t.kinetic_energy, 1e-9) << "no drift left to remove";
    }
}

TEST(GasGenerator, FixedSpeedHasThatSpeedInRandomDirections) {
    ParticleGenerator g = gas_block(4000, 0.5, 1.0);
    g.velocity_kind = "fixed_speed";
    g.speed = 2.5;
    const auto s = generate_initial_state(scene_with(150, 150, {g}));
    double mean_cos = 0, mean_sin = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_NEAR(std::hypot(s.vx[i], s.vy[i]), 2.5, 1e-12);
        mean_cos += s.vx[i] / 2.5 / 4000;
        mean_sin += s.vy[i] / 2.5 / 4000;
    }
    // cos and sin of a uniform angle: mean 0, variance 1/2.
    EXPECT_NEAR(mean_cos, 0.0, 4 * std::sqrt(0.5 / 4000));
    EXPECT_NEAR(mean_sin, 0.0, 4 * std::sqrt(0.5 / 4000));
}

TEST(GasGenerator, ZeroVelocityByDefault) {
    const auto s = generate_initial_state(scene_with(20, 20, {gas_block(50, 0.5, 1.0)}));
    for (std::size_t i = 0; i < s.size(); ++i) EXPECT_TRUE(s.vx[i] == 0 && s.vy[i] == 0);
}

TEST(GasGenerator, UniformRadiiCoverTheRangeWithTheRightMean) {
    ParticleGenerator g = gas_block(5000, 0, 1.0);
    g.radius_kind = "uniform";
    g.radius_min = 0.2;
    g.radius_max = 0.6;
    const auto s = generate_initial_state(scene_with(150, 150, {g}));
    double mean = 0;
    for (double r : s.radius) {
        EXPECT_TRUE(r >= 0.2 && r <= 0.6);
        mean += r / 5000;
    }
    // Uniform on [a, b]: mean (a + b)/2, standard deviation (b - a)/sqrt(12).
    EXPECT_NEAR(mean, 0.4, 4 * 0.4 / std::sqrt(12.0 * 5000));
}

TEST(GasGenerator, BidisperseHasTheExactFractionAndDensityMasses) {
    ParticleGenerator g = gas_block(1001, 0, 1.0);
    g.mass.reset();
    g.density = 3.0;
    g.radius_kind = "bidisperse";
    g.radius_small = 0.4;
    g.radius_large = 0.56;
    g.fraction_large = 0.3;
    const Scene scene = scene_with(70, 70, {g}, Boundary::periodic);
    const auto s = generate_initial_state(scene);
    int large = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_TRUE(s.radius[i] == 0.4 || s.radius[i] == 0.56);
        large += s.radius[i] == 0.56;
        EXPECT_DOUBLE_EQ(s.mass[i], 3.0 * pi * s.radius[i] * s.radius[i]);  // areal density
    }
    EXPECT_EQ(large, 300);  // round(0.3 * 1001)
    EXPECT_EQ(test::brute_force_overlapping_pairs(scene, s), 0);
}

TEST(GasGenerator, AvoidsExplicitDisksAndEarlierBlocks) {
    ParticleGenerator list;
    list.kind = "list";
    list.disks = {{15, 15, 0, 0, 5.0, 1, true}};  // a big stone in the middle
    const Scene scene = scene_with(30, 30, {list, gas_block(300, 0.5, 1.0), gas_block(200, 0.3, 1.0)});
    const auto s = generate_initial_state(scene);
    ASSERT_EQ(s.size(), 501u);
    EXPECT_EQ(s.inv_mass[0], 0.0);  // a stone has inverse mass 0
    EXPECT_EQ(s.mass[0], 1.0);
    EXPECT_EQ(test::brute_force_overlapping_pairs(scene, s), 0);
}

TEST(GasGenerator, MassFromDensityMustBeFiniteAndPositive) {
    ParticleGenerator g = gas_block(1, 1e-200, 1.0);
    g.mass.reset();
    g.density = 1.0;  // m = pi 1e-400 underflows to 0
    EXPECT_THROW(generate_initial_state(scene_with(10, 10, {g})), SceneError);
}

TEST(GasGenerator, TooDenseForRandomSequentialAdditionIsAClearError) {
    // phi = 80 pi 0.25 / 100 = 0.63 > 0.547, the RSA jamming limit.
    const Scene scene = scene_with(10, 10, {gas_block(80, 0.5, 1.0)});
    try {
        generate_initial_state(scene);
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("[[particles]][1]"), std::string::npos) << message;
        EXPECT_NE(message.find("0.628"), std::string::npos) << message;  // the requested area fraction
        EXPECT_NE(message.find("0.547"), std::string::npos) << message;
        EXPECT_NE(message.find("lattice"), std::string::npos) << message;
    }
}

// The attempt budget is max(1000 N, 10^6); a hopeless request must not spend it all. At area
// fraction 0.8 RSA stalls near 0.547, and the generator sees that the attempts per placed disk
// times the disks left exceed the budget left.
TEST(GasGenerator, AHopelessPackingGivesUpLongBeforeTheBudgetIsSpent) {
    const std::int64_t count = 20000;
    const double side = std::sqrt(double(count) * pi * 0.25 / 0.8);
    const Scene scene = scene_with(side, side, {gas_block(count, 0.5, 1.0)}, Boundary::periodic);
    try {
        generate_initial_state(scene);
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        const auto after = message.find(" disks after ");
        ASSERT_NE(after, std::string::npos) << message;
        const long long attempts = std::stoll(message.substr(after + 13));
        EXPECT_LT(attempts, 1000 * count / 10) << message;
        EXPECT_NE(message.find("area fraction in the region is 0.8"), std::string::npos) << message;
    }
}

TEST(GasGenerator, BeyondTheDensestPackingIsRefusedWithoutAnAttempt) {
    // 120 disks of radius 0.5 in 10 x 10: phi = 0.942 > pi/sqrt(12) = 0.9069.
    const Scene scene = scene_with(10, 10, {gas_block(120, 0.5, 1.0)}, Boundary::periodic);
    try {
        generate_initial_state(scene);
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("area fraction in the region is 0.942"), std::string::npos) << message;
        EXPECT_NE(message.find("beyond pi/sqrt(12) = 0.9069"), std::string::npos) << message;
        EXPECT_EQ(message.find("attempts"), std::string::npos) << message;
    }
}

TEST(Seeding, SameSeedSameStateOtherSeedOtherState) {
    ParticleGenerator g = gas_block(500, 0.5, 1.0);
    g.velocity_kind = "maxwell";
    g.temperature = 1;
    const auto a = generate_initial_state(scene_with(40, 40, {g}, Boundary::reflect, 11));
    const auto b = generate_initial_state(scene_with(40, 40, {g}, Boundary::reflect, 11));
    const auto c = generate_initial_state(scene_with(40, 40, {g}, Boundary::reflect, 12));
    EXPECT_EQ(state_hash(a), state_hash(b));
    EXPECT_EQ(a.x, b.x);
    EXPECT_NE(state_hash(a), state_hash(c));
    EXPECT_NE(a.x[0], c.x[0]);
}

ParticleGenerator lattice_block(const std::string& kind, std::int64_t count, std::int64_t columns, double spacing) {
    ParticleGenerator g;
    g.kind = "lattice";
    g.lattice = kind;
    g.count = count;
    g.columns = columns;
    g.spacing = spacing;
    g.radius = 0.5;
    g.mass = 1.0;
    return g;
}

TEST(LatticeGenerator, SquareLatticeIsCentredWithTheGivenSpacing) {
    const auto s = generate_initial_state(scene_with(20, 10, {lattice_block("square", 12, 4, 1.5)}));
    ASSERT_EQ(s.size(), 12u);
    // 4 columns x 3 rows, centres spanning 3 x 1.5 by 2 x 1.5, centred at (10, 5).
    EXPECT_DOUBLE_EQ(s.x[0], 10 - 2.25);
    EXPECT_DOUBLE_EQ(s.y[0], 5 - 1.5);
    EXPECT_DOUBLE_EQ(s.x[11], 10 + 2.25);
    EXPECT_DOUBLE_EQ(s.y[11], 5 + 1.5);
    EXPECT_NEAR(s.x[1] - s.x[0], 1.5, 1e-12);
    EXPECT_NEAR(s.y[4] - s.y[0], 1.5, 1e-12);
}

TEST(LatticeGenerator, HexagonalLatticeHasSixNeighboursAtTheSpacing) {
    const double a = 1.2;
    const auto s = generate_initial_state(scene_with(30, 30, {lattice_block("hexagonal", 100, 10, a)}));
    ASSERT_EQ(s.size(), 100u);
    // Every disk's nearest neighbours sit at distance a; an interior disk has six of them.
    std::vector<int> neighbours(s.size(), 0);
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = 0; j < s.size(); ++j) {
            if (i == j) continue;
            const double d = std::hypot(s.x[i] - s.x[j], s.y[i] - s.y[j]);
            EXPECT_GT(d, a * (1 - 1e-12));
            if (d < a * (1 + 1e-12)) ++neighbours[i];
        }
    const std::size_t interior = 4 * 10 + 5;  // row 4, column 5
    EXPECT_EQ(neighbours[interior], 6);
    EXPECT_NEAR(s.y[10] - s.y[0], a * std::sqrt(3.0) / 2, 1e-12);  // row spacing
    EXPECT_NEAR(s.x[10] - s.x[0], a / 2, 1e-12);                   // odd rows shifted
}

TEST(LatticeGenerator, LatticeLargerThanTheRegionIsAClearError) {
    // 10 columns at spacing 1.2 need 10.8 + 1 > 10.
    const Scene scene = scene_with(10, 10, {lattice_block("square", 20, 10, 1.2)});
    try {
        generate_initial_state(scene);
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("[[particles]][1] (lattice)"), std::string::npos) << message;
        EXPECT_NE(message.find("region"), std::string::npos) << message;
    }
}

TEST(LatticeGenerator, TouchingDisksAtSpacingTwoRadiiAreAccepted) {
    const Scene scene = scene_with(12, 12, {lattice_block("hexagonal", 100, 10, 1.0)});
    EXPECT_EQ(generate_initial_state(scene).size(), 100u);
}

TEST(GasScene, BoxIsSizedForTheAreaFraction) {
    GasSceneSpec spec;
    spec.count = 100000;
    spec.area_fraction = 0.3;
    spec.radius = 0.25;
    spec.aspect = 2.0;
    spec.boundary = Boundary::periodic;
    const Scene scene = make_gas_scene(spec);
    const double phi = double(spec.count) * pi * 0.25 * 0.25 / (scene.world.width() * scene.world.height());
    EXPECT_NEAR(phi, 0.3, 1e-12);
    EXPECT_NEAR(scene.world.width() / scene.world.height(), 2.0, 1e-12);
    EXPECT_TRUE(scene.periodic());
    const auto s = generate_initial_state(scene);
    EXPECT_EQ(s.size(), 100000u);
}

TEST(GasScene, RejectsAnAreaFractionBeyondJamming) {
    GasSceneSpec spec;
    spec.area_fraction = 0.6;
    EXPECT_THROW(make_gas_scene(spec), SceneError);
    spec.area_fraction = 0.3;
    spec.count = 0;
    EXPECT_THROW(make_gas_scene(spec), SceneError);
}

// The lattice placement reaches area fractions random placement cannot (up to pi/4), keeps
// every disk apart with its jitter, and can remove the centre-of-mass drift.
TEST(GasScene, LatticePlacementHoldsDenseGasesWithoutOverlap) {
    GasSceneSpec spec;
    spec.count = 1000;
    spec.area_fraction = 0.7;
    spec.placement = GasPlacement::lattice;
    spec.boundary = Boundary::periodic;
    spec.remove_drift = true;
    const GasCase gas = make_gas(spec);
    ASSERT_EQ(gas.initial.size(), 1000u);
    const double area = gas.scene.world.width() * gas.scene.world.height();
    EXPECT_NEAR(1000 * pi * 0.25 / area, 0.7, 1e-12);
    double px = 0, py = 0;
    for (std::size_t i = 0; i < gas.initial.size(); ++i) px += gas.initial.vx[i], py += gas.initial.vy[i];
    EXPECT_NEAR(px, 0, 1e-10);
    EXPECT_NEAR(py, 0, 1e-10);
    EXPECT_EQ(compute_metrics(gas.scene, gas.initial, 0.0).overlapping_pairs, 0);

    // Jittered, shuffled, uniform velocities (the benchmarks' gas): still apart, velocities
    // within the bound, and not listed row by row.
    spec.area_fraction = 0.3;
    spec.boundary = Boundary::reflect;
    spec.jitter = spec.shuffle = spec.uniform_velocities = true;
    spec.remove_drift = false;
    const GasCase jittered = make_gas(spec);
    EXPECT_EQ(compute_metrics(jittered.scene, jittered.initial, 0.0).overlapping_pairs, 0);
    for (std::size_t i = 0; i < jittered.initial.size(); ++i) EXPECT_LE(std::fabs(jittered.initial.vx[i]), 1.0);
    EXPECT_FALSE(std::is_sorted(jittered.initial.y.begin(), jittered.initial.y.end())) << "shuffled";
}

TEST(GasScene, LatticeRefusesWhatASquareLatticeCannotHold) {
    GasSceneSpec spec;
    spec.placement = GasPlacement::lattice;
    spec.area_fraction = 0.8;  // beyond pi/4
    EXPECT_THROW(make_gas(spec), SceneError);
    spec.area_fraction = 0.5;
    spec.aspect = 2;
    EXPECT_THROW(make_gas(spec), SceneError);
    EXPECT_THROW(make_gas_scene(spec), SceneError) << "a lattice gas has no scene of its own";
}

}  // namespace
}  // namespace collide
