// Statistical physics of the `event` backend: relaxation to the Maxwell-Boltzmann
// distribution and the equation of state of the hard-disk fluid. Fixed seeds; each test
// runs a few 1e5 collisions (about a second in a release build).
#include <gtest/gtest.h>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "reference/event/event_solver.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

// Pearson chi-square test of the disks' speeds against the 2D Maxwell-Boltzmann (Rayleigh)
// distribution P(v) = v/s^2 exp(-v^2 / (2 s^2)), s^2 = kT/m, with `bins` bins of equal
// probability. Returns the p-value (gsl_cdf_chisq_Q with bins - 1 degrees of freedom: s is
// not fitted, it follows from the conserved energy).
double maxwell_boltzmann_p_value(const ParticleState<double>& s, double kt_over_m, int bins) {
    std::vector<double> edges;
    for (int k = 1; k < bins; ++k) edges.push_back(gsl_cdf_rayleigh_Pinv(double(k) / bins, std::sqrt(kt_over_m)));
    std::vector<double> observed(std::size_t(bins), 0.0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double v = std::hypot(s.vx[i], s.vy[i]);
        observed[std::size_t(std::upper_bound(edges.begin(), edges.end(), v) - edges.begin())] += 1;
    }
    const double expected = double(s.size()) / bins;
    double chi2 = 0;
    for (double o : observed) chi2 += (o - expected) * (o - expected) / expected;
    return gsl_cdf_chisq_Q(chi2, bins - 1);
}

TEST(EventStatistics, DiluteGasRelaxesToMaxwellBoltzmann) {
    // 2000 disks of r = 1/2 at area fraction 0.05 in a reflecting box, all with speed 1 in
    // random directions. The mean free time is about 4, so t = 100 is ~25 collisions per disk.
    const std::size_t n = 2000;
    const double box = std::sqrt(double(n) * M_PI * 0.25 / 0.05);
    const Scene scene = test::box_scene(box, box);
    ParticleState<double> initial = test::random_gas(scene, n, 0.5, 5);
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI);
    for (std::size_t i = 0; i < n; ++i) {
        const double a = angle(rng);
        initial.vx[i] = std::cos(a), initial.vy[i] = std::sin(a);
    }
    // Energy is conserved (e = 1 everywhere): kT/m = E/N = 1/2 exactly (2D equipartition).
    const double kt = 0.5;
    const int bins = 20;
    // The test can fail: the initial equal-speed state is rejected outright.
    EXPECT_LT(maxwell_boltzmann_p_value(initial, kt, bins), 1e-10);

    EventSolver solver;
    solver.load(scene, initial);
    solver.advance_to(100);
    ParticleState<double> relaxed;
    solver.read_state(relaxed);
    EXPECT_GT(solver.stats().contacts, 5 * std::int64_t(n));  // > 10 collisions per disk
    EXPECT_GT(maxwell_boltzmann_p_value(relaxed, kt, bins), 1e-3);
}

// Henderson's equation of state for hard disks (D. Henderson, Mol. Phys. 30 (1975) 971):
//   Z = P A / (N kT) = (1 + phi^2 / 8) / (1 - phi)^2,
// accurate to a few 1e-3 relative in the fluid up to phi ~ 0.5.
double henderson_z(double phi) { return (1 + phi * phi / 8) / ((1 - phi) * (1 - phi)); }

struct PressureEstimate {
    double mean, standard_error;
};

// Z from the collision virial of a periodic elastic gas (docs/event-driven.md):
//   Z = 1 + sum_collisions |d| J / (2 t K),  K the (constant) kinetic energy = N kT in 2D.
// Block averaging: the run is cut into `blocks` blocks, each long enough (~30 collisions per
// disk) for block means to be independent; the error bar is the standard error of the mean.
PressureEstimate measure_z(double phi, std::size_t n, std::uint64_t seed) {
    const double box = std::sqrt(double(n) * M_PI * 0.25 / phi);
    const Scene scene = test::box_scene(box, box, Boundary::periodic);
    ParticleState<double> initial = test::random_gas(scene, n, 0.5, seed);
    double px = 0, py = 0, kinetic = 0;
    for (std::size_t i = 0; i < n; ++i) px += initial.vx[i], py += initial.vy[i];
    for (std::size_t i = 0; i < n; ++i) {
        initial.vx[i] -= px / double(n), initial.vy[i] -= py / double(n);  // no centre-of-mass drift
        kinetic += 0.5 * (initial.vx[i] * initial.vx[i] + initial.vy[i] * initial.vy[i]);
    }
    EventSolver solver;
    solver.load(scene, initial);
    // Equilibrate for ~20 collisions per disk, measuring the collision rate on the way.
    double t = 0;
    while (solver.stats().contacts < 10 * std::int64_t(n)) solver.advance_to(t += 1);
    const double block_time = 15.0 * double(n) / solver.stats().counters.at("collisions_per_time");
    const int blocks = 20;
    std::vector<double> z;
    double virial = solver.stats().counters.at("virial_sum");
    for (int b = 0; b < blocks; ++b) {
        solver.advance_to(t += block_time);
        const double v = solver.stats().counters.at("virial_sum");
        z.push_back(1 + (v - virial) / (2 * block_time * kinetic));
        virial = v;
    }
    double mean = 0, var = 0;
    for (double x : z) mean += x / blocks;
    for (double x : z) var += (x - mean) * (x - mean) / (blocks - 1);
    return {mean, std::sqrt(var / blocks)};
}

void expect_henderson(double phi) {
    const PressureEstimate z = measure_z(phi, 1000, 17);
    const double expected = henderson_z(phi);
    std::printf("area fraction %.1f: Z = %.5f +- %.5f (standard error, 20 blocks), Henderson %.5f\n", phi, z.mean,
                z.standard_error, expected);
    // The error bar must be small enough for the comparison to mean something (1%), and the
    // measurement must agree with Henderson's Z within 3 standard errors.
    EXPECT_LT(z.standard_error, 0.01 * expected);
    EXPECT_NEAR(z.mean, expected, 3 * z.standard_error) << "phi = " << phi << ": Z = " << z.mean << " +- "
                                                        << z.standard_error << ", Henderson " << expected;
}

TEST(EventStatistics, HendersonEquationOfStateAtAreaFraction02) { expect_henderson(0.2); }
TEST(EventStatistics, HendersonEquationOfStateAtAreaFraction04) { expect_henderson(0.4); }

TEST(EventStatistics, ReflectingWallPressureMatchesVirialPressure) {
    // In a dilute gas the mechanical pressure on the walls and the ideal-gas value
    // N kT / A agree up to the excluded-area correction (Z - 1 ~ 2 phi at low phi).
    const std::size_t n = 500;
    const double phi = 0.02, box = std::sqrt(double(n) * M_PI * 0.25 / phi);
    const Scene scene = test::box_scene(box, box);
    const auto initial = test::random_gas(scene, n, 0.5, 23);
    double kinetic = 0;
    for (std::size_t i = 0; i < n; ++i) kinetic += 0.5 * (initial.vx[i] * initial.vx[i] + initial.vy[i] * initial.vy[i]);
    EventSolver solver;
    solver.load(scene, initial);
    solver.advance_to(2000);
    const double ideal = kinetic / (box * box);  // P = N kT / A with N kT = K in 2D
    EXPECT_NEAR(solver.stats().counters.at("pressure") / ideal, henderson_z(phi), 0.05);
}

}  // namespace
}  // namespace collide
