// The pressure record of a run (core/thermo/pressure_record.h): the counters of a series, the
// record of an event-driven run of a periodic gas, an error bar that matches the scatter
// between seeds, and no record where the scene does not qualify.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/backend_registry.h"
#include "core/run_driver.h"
#include "core/thermo/pressure_record.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

const char* const counter_names[] = {"beta_pressure",           "beta_pressure_error",
                                     "beta_pressure_correlation_time", "beta_pressure_equilibration",
                                     "beta_pressure_batches",   "psi6_traversals",
                                     "psi6_mixed"};

// Independent entries of mean 5 and standard deviation 1, after a start far off (a drift the
// equilibration cut must remove); lengths in the entry's unit of 0.5.
TEST(PressureRecord, CountersOfASeries) {
    PressureSeries s;
    std::mt19937_64 rng(5);
    std::normal_distribution<double> noise(5, 1);
    for (int k = 0; k < 4000; ++k) s.beta_pressure.push_back(noise(rng) + (k < 200 ? 20 : 0));
    s.entry_length = 0.5;
    s.psi6_phase = {0.0, 1.0};
    s.area_fraction = 0.70;
    const auto c = pressure_counters(s);
    EXPECT_NEAR(c.at("beta_pressure"), 5.0, 4 / std::sqrt(3800.0));
    EXPECT_NEAR(c.at("beta_pressure_error"), 1 / std::sqrt(double(4000 - c.at("beta_pressure_equilibration") / 0.5)), 0.005);
    EXPECT_GE(c.at("beta_pressure_equilibration"), 200 * 0.5);
    EXPECT_LE(c.at("beta_pressure_equilibration"), 400 * 0.5);
    EXPECT_NEAR(c.at("beta_pressure_correlation_time"), 0.5 * 0.5, 0.1);
    EXPECT_EQ(c.at("beta_pressure_batches"), 20);
    EXPECT_EQ(c.at("psi6_traversals"), 0);
    EXPECT_EQ(c.at("psi6_mixed"), 0);  // dense and the phase did not turn: not mixed
    s.area_fraction = 0.5;
    EXPECT_EQ(pressure_counters(s).at("psi6_mixed"), 1);  // the check applies from eta 0.69
}

// The collision-rate series of the same windows gets its own batch means; a series without
// one (a sampler's) gets no collision-rate counters.
TEST(PressureRecord, CollisionRateCountersOfASeries) {
    PressureSeries s;
    std::mt19937_64 rng(7);
    std::normal_distribution<double> pressure(5, 1), rate(12, 2);
    for (int k = 0; k < 2000; ++k) s.beta_pressure.push_back(pressure(rng)), s.collision_rate.push_back(rate(rng));
    const auto c = pressure_counters(s);
    EXPECT_NEAR(c.at("collision_rate_mean"), 12, 4 * 2 / std::sqrt(2000.0));
    EXPECT_NEAR(c.at("collision_rate_error"), 2 / std::sqrt(2000.0), 0.3 * 2 / std::sqrt(2000.0));
    s.collision_rate.clear();
    EXPECT_EQ(pressure_counters(s).count("collision_rate_mean"), 0u);
}

// A periodic gas of `n` equal disks at area fraction eta with the scene's seed.
struct Gas {
    Scene scene;
    ParticleState<double> initial;
};
Gas periodic_gas(std::size_t n, double eta, std::uint64_t seed, Boundary boundary = Boundary::periodic) {
    const double radius = 0.5, box = std::sqrt(double(n) * std::numbers::pi * radius * radius / eta);
    Gas g{test::box_scene(box, box, boundary), {}};
    g.scene.run.duration = 40;
    g.scene.run.output_interval = 1;
    g.initial = test::random_gas(g.scene, n, radius, seed);
    return g;
}

SolverStats event_run(const Gas& g, const char* backend = "event") {
    auto solver = find_backend(backend).create({});
    return run_scene(g.scene, *solver, g.initial).stats;
}

TEST(PressureRecord, EventRunOfAPeriodicGasRecordsEveryCounter) {
    for (const char* backend : {"event", "event-plain"}) {
        const SolverStats stats = event_run(periodic_gas(100, 0.3, 1), backend);
        for (const char* name : counter_names) EXPECT_TRUE(stats.counters.count(name)) << backend << ": " << name;
        // 40 outputs cut into windows of 0.04: 1000 entries, 20 batches.
        EXPECT_EQ(stats.counters.at("beta_pressure_batches"), 20) << backend;
        EXPECT_GT(stats.counters.at("beta_pressure_error"), 0) << backend;
        EXPECT_LT(stats.counters.at("beta_pressure_error"), 0.05 * stats.counters.at("beta_pressure")) << backend;
        // The windows' collision rates average to the run's own count: 2 C / (N t) over the
        // part after the cut, so within a few errors of the whole run's rate.
        const double whole_run = 2 * double(stats.contacts) / (100 * 40.0);
        EXPECT_NEAR(stats.counters.at("collision_rate_mean"), whole_run, 5 * stats.counters.at("collision_rate_error") + 0.01 * whole_run)
            << backend;
    }
}

// The stated error is the scatter one run has about the true mean: over 8 seeds the standard
// deviation of beta_pressure is within a factor 2 of the mean stated error.
TEST(PressureRecord, ErrorMatchesTheScatterBetweenSeeds) {
    std::vector<double> values, errors;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const SolverStats stats = event_run(periodic_gas(100, 0.4, seed));
        values.push_back(stats.counters.at("beta_pressure"));
        errors.push_back(stats.counters.at("beta_pressure_error"));
    }
    double mean = 0, mean_error = 0, spread = 0;
    for (std::size_t k = 0; k < values.size(); ++k) mean += values[k] / 8, mean_error += errors[k] / 8;
    for (double v : values) spread += (v - mean) * (v - mean) / 7;
    spread = std::sqrt(spread);
    EXPECT_GT(spread, 0.5 * mean_error);
    EXPECT_LT(spread, 2 * mean_error);
}

TEST(PressureRecord, WalledCoolingOrColdScenesRecordNone) {
    const Gas walls = periodic_gas(100, 0.3, 1, Boundary::reflect);
    EXPECT_FALSE(event_run(walls).counters.count("beta_pressure"));
    EXPECT_TRUE(pressure_record_refusal(walls.scene, walls.initial));
    Gas cooling = periodic_gas(100, 0.3, 1);
    cooling.scene.physics.restitution = 0.9;
    EXPECT_TRUE(pressure_record_refusal(cooling.scene, cooling.initial));
    EXPECT_FALSE(event_run(cooling).counters.count("beta_pressure"));
    Gas at_rest = periodic_gas(100, 0.3, 1);  // every disk moving with the centre of mass
    for (std::size_t i = 0; i < at_rest.initial.size(); ++i) at_rest.initial.vx[i] = 1, at_rest.initial.vy[i] = 0;
    EXPECT_TRUE(pressure_record_refusal(at_rest.scene, at_rest.initial));
    EXPECT_FALSE(event_run(at_rest).counters.count("beta_pressure"));
}

TEST(PressureRecord, WindowsGiveAtLeastAThousandEntries) {
    EXPECT_EQ(pressure_windows_per_output(40), 25u);
    EXPECT_EQ(pressure_windows_per_output(3000), 1u);
    EXPECT_EQ(pressure_windows_per_output(0), 1u);
}

}  // namespace
}  // namespace collide
