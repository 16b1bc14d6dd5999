// `metropolis` (sampling/metropolis_sampler.h): legal configurations in the four-disk box with
// walls, the step tuned to the stated acceptance, and its contact-value pressure against the
// lifts of `ecmc` in the same periodic box (two routes that share no estimator code).
#include <gtest/gtest.h>

#include <cmath>

#include "core/run_driver.h"
#include "core/scene/gas_scene.h"
#include "sampling/ecmc_sampler.h"
#include "sampling/metropolis_sampler.h"
#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

// Li et al.'s teaching system: 4 disks of radius 0.15 in a unit square with walls.
TEST(MetropolisSampler, SamplesTheFourDiskBoxAtTheStatedAcceptance) {
    Scene scene = box_scene(1, 1, Boundary::reflect);
    scene.run.sweeps = 20000;
    const ParticleState<double> start =
        make_state({{0.25, 0.25, 0, 0, 0.15, 1}, {0.75, 0.25, 0, 0, 0.15, 1}, {0.25, 0.75, 0, 0, 0.15, 1}, {0.75, 0.75, 0, 0, 0.15, 1}});
    MetropolisSampler sampler;
    const RunResult r = run_scene(scene, sampler, start);
    EXPECT_EQ(r.stats.steps, 20000);
    EXPECT_NEAR(r.stats.counters.at("acceptance"), default_metropolis_acceptance, 0.05);
    EXPECT_EQ(brute_force_overlapping_pairs(scene, r.final_state), 0);
    for (const Metrics& m : r.series) EXPECT_EQ(m.max_wall_penetration, 0) << "t = " << m.time;
    EXPECT_GT(r.stats.counters.at("beta_pressure"), 0);
    EXPECT_GT(r.stats.counters.at("beta_pressure_error"), 0);
    bool moved = false;
    for (std::size_t i = 0; i < 4; ++i) moved = moved || r.final_state.x[i] != start.x[i];
    EXPECT_TRUE(moved);
}

TEST(MetropolisSampler, ContactPressureAgreesWithTheLiftsOfEcmc) {
    GasSceneSpec spec;
    spec.count = 64;
    spec.area_fraction = 0.4;
    spec.boundary = Boundary::periodic;
    spec.placement = GasPlacement::lattice;
    spec.jitter = true;
    GasCase gas = make_gas(spec);
    gas.scene.name = "periodic_64";
    gas.scene.run.sweeps = 40000;
    gas.scene.run.chains = 40000;
    MetropolisSampler metropolis;
    EcmcSampler ecmc;
    const SolverStats a = run_scene(gas.scene, metropolis, gas.initial).stats;
    const SolverStats b = run_scene(gas.scene, ecmc, gas.initial).stats;
    const double pa = a.counters.at("beta_pressure"), pb = b.counters.at("beta_pressure");
    const double combined = std::hypot(a.counters.at("beta_pressure_error"), b.counters.at("beta_pressure_error"));
    // The straight-line extrapolation over 5 % of sigma leaves a bias of order 1e-3 relative here.
    EXPECT_NEAR(pa, pb, 4 * combined + 2e-3 * pb) << "metropolis " << pa << ", ecmc " << pb << ", combined error " << combined;
}

}  // namespace
}  // namespace collide::test
