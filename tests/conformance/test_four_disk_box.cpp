// The four-disk box (Li, Nishikawa, Hoellmer, Carillo, Maggs, Krauth, J. Chem. Phys. 157,
// 234111 (2022); Krauth, "Statistical Mechanics: Algorithms and Computations", ch. 2): four
// disks of radius 0.15 in a unit square with walls, the smallest system in which molecular
// dynamics and sampling must agree. The exact solvers `event` and `event-plain` are held to a
// plain Metropolis sampler of the same box, written here and sharing no code with them:
//
//  - wall pressure. MD: the momentum given to the four walls per unit time over kT = K / N
//    (walls: N degrees of freedom, core/thermo/kinetic_temperature.h), beta F. Sampler: the
//    contact theorem for a hard wall, beta F = sum over walls of the line density of centres at
//    contact, i.e. the mean number of (disk, wall) pairs with gap (distance to the wall - r) in
//    [0, h), over h, as h -> 0.
//  - pair contacts. MD: the collision virial rate W over kT is (sigma / 2) times the pair
//    contact density C = sum_pairs <delta(r_ij - sigma)> (docs/validation.md, "The equation of
//    state at finite N"): C = Delta V / (sigma Delta t kT). Sampler: the mean number of pairs
//    with r_ij - sigma in [0, h), over h, as h -> 0.
// Both sampler densities are extrapolated to contact from two bins of width h (linear in the
// gap; the curvature leaves O(h^2)). Error bars: 20 batch means on both sides.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "conformance.h"
#include "core/run_driver.h"
#include "core/scene/scene_loader.h"
#include "core/thermo/kinetic_temperature.h"
#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

constexpr double radius = 0.15, sigma = 2 * radius, side = 1.0;
constexpr int disks = 4, batches = 20;

struct Estimate {
    double mean = 0, error = 0;
};

Estimate batch_mean(const std::vector<double>& b) {
    double mean = 0, var = 0;
    for (double x : b) mean += x / double(b.size());
    for (double x : b) var += (x - mean) * (x - mean) / double(b.size() - 1);
    return {mean, std::sqrt(var / double(b.size()))};
}

struct BoxStatistics {
    Estimate wall_force;       // beta F over all four walls
    Estimate pair_contact;     // sum over pairs of <delta(r_ij - sigma)>
};

// --- Molecular dynamics: one of the exact solvers -------------------------------------------

// The box, one scene file shared with the course's lab (docs/course/lab_four_disks.py).
Scene four_disk_scene() { return load_scene(test::scene_file("physics/four_disk_box.toml")); }

BoxStatistics molecular_dynamics(const std::string& backend, double duration) {
    const Scene scene = four_disk_scene();
    const ParticleState<double> initial = generate_initial_state(scene);
    const double kT = kinetic_temperature(scene, initial).kT();
    auto solver = find_backend(backend).create(BackendOptions{});
    solver->load(scene, initial);
    const double warm_up = 0.05 * duration, block = (duration - warm_up) / batches;
    solver->advance_to(warm_up);
    std::vector<double> wall, pair;
    SolverStats before = solver->stats();
    for (int b = 1; b <= batches; ++b) {
        solver->advance_to(warm_up + b * block);
        const SolverStats after = solver->stats();
        const double impulse = after.counters.at("wall_impulse") - before.counters.at("wall_impulse");
        const double virial = after.counters.at("virial_sum") - before.counters.at("virial_sum");
        wall.push_back(impulse / (block * kT));
        pair.push_back(virial / (sigma * block * kT));
        before = after;
    }
    return {batch_mean(wall), batch_mean(pair)};
}

// --- Metropolis: the uniform measure of non-overlapping configurations ----------------------

class MetropolisBox {
public:
    explicit MetropolisBox(unsigned seed) : rng_(seed) {
        x_ = {0.25, 0.75, 0.25, 0.75};
        y_ = {0.25, 0.25, 0.75, 0.75};
    }

    // One attempted move of a random disk by a uniform step in [-delta, delta]^2; rejected if it
    // leaves the box or overlaps another disk.
    void move() {
        const int i = int(uniform_(rng_) * disks);
        const double nx = x_[i] + delta * (2 * uniform_(rng_) - 1), ny = y_[i] + delta * (2 * uniform_(rng_) - 1);
        if (nx < radius || nx > side - radius || ny < radius || ny > side - radius) return;
        for (int j = 0; j < disks; ++j)
            if (j != i && (nx - x_[j]) * (nx - x_[j]) + (ny - y_[j]) * (ny - y_[j]) < sigma * sigma) return;
        x_[i] = nx, y_[i] = ny;
    }

    // Adds this configuration's counts in the two bins [0, h) and [h, 2h) of wall and pair gaps.
    void count(double h, std::array<double, 2>& wall, std::array<double, 2>& pair) const {
        auto add = [h](double gap, std::array<double, 2>& bins) {
            if (gap < 2 * h) bins[gap < h ? 0 : 1] += 1;
        };
        for (int i = 0; i < disks; ++i)
            for (double gap : {x_[i] - radius, side - radius - x_[i], y_[i] - radius, side - radius - y_[i]}) add(gap, wall);
        for (int i = 0; i < disks; ++i)
            for (int j = i + 1; j < disks; ++j) add(std::hypot(x_[i] - x_[j], y_[i] - y_[j]) - sigma, pair);
    }

private:
    static constexpr double delta = 0.1;
    std::mt19937_64 rng_;
    std::uniform_real_distribution<double> uniform_{0.0, 1.0};
    std::array<double, disks> x_{}, y_{};
};

// The density at gap 0 from two bin averages (centres h/2 and 3h/2), linear in the gap.
double at_contact(const std::array<double, 2>& bins, double samples, double h) {
    const double first = bins[0] / (samples * h), second = bins[1] / (samples * h);
    return first - 0.5 * (second - first);
}

BoxStatistics metropolis(long sweeps, double h) {
    MetropolisBox box(20221215);
    for (long s = 0; s < 1000; ++s)
        for (int k = 0; k < disks; ++k) box.move();
    std::vector<double> wall, pair;
    const long per_batch = sweeps / batches;
    for (int b = 0; b < batches; ++b) {
        std::array<double, 2> wall_bins{}, pair_bins{};
        for (long s = 0; s < per_batch; ++s) {
            for (int k = 0; k < disks; ++k) box.move();
            box.count(h, wall_bins, pair_bins);
        }
        wall.push_back(at_contact(wall_bins, double(per_batch), h));
        pair.push_back(at_contact(pair_bins, double(per_batch), h));
    }
    return {batch_mean(wall), batch_mean(pair)};
}

void expect_agree(const Estimate& md, const Estimate& mc, const std::string& what) {
    const double combined = std::hypot(md.error, mc.error);
    EXPECT_LE(std::abs(md.mean - mc.mean), 4 * combined)
        << what << ": molecular dynamics " << md.mean << " +- " << md.error << ", Metropolis " << mc.mean << " +- "
        << mc.error;
    // Resolving power: both sides to better than 1 %, so a wrong temperature (kT = K / (N - 1),
    // the periodic definition, reads 25 % low) or a lost factor cannot hide in the error bars.
    EXPECT_LT(md.error, 0.01 * md.mean) << what;
    EXPECT_LT(mc.error, 0.01 * mc.mean) << what;
}

TEST(FourDiskBox, ExactSolversAndMetropolisGiveTheSameWallPressureAndPairContacts) {
    const BoxStatistics mc = metropolis(4'000'000, 0.004);
    for (const char* backend : {"event", "event-plain"}) {
        const BoxStatistics md = molecular_dynamics(backend, 20000);
        expect_agree(md.wall_force, mc.wall_force, std::string(backend) + " wall pressure beta F");
        expect_agree(md.pair_contact, mc.pair_contact, std::string(backend) + " pair contact density");
    }
}

// A sampling backend's wall pressure in this box (its beta_pressure: beta P d^2, the force on
// the walls per unit wall length) against `event`'s momentum flux through the walls,
// beta F / perimeter * sigma^2. `length` sets the scene's run ([run] sweeps or chains).
void expect_events_wall_pressure(const std::string& backend, void (*length)(RunSettings&)) {
    Scene scene = four_disk_scene();
    length(scene.run);
    scene.run.duration = 1;
    scene.run.output_interval = 1;
    auto sampler = find_backend(backend).create(BackendOptions{});
    const RunResult sampled = run_scene(scene, *sampler, generate_initial_state(scene));
    const Estimate mc{sampled.stats.counters.at("beta_pressure"), sampled.stats.counters.at("beta_pressure_error")};
    const Estimate force = molecular_dynamics("event", 20000).wall_force;
    const double per_length = sigma * sigma / (4 * side);
    const Estimate md{force.mean * per_length, force.error * per_length};
    // The two numbers docs/monte-carlo.md quotes.
    std::printf("four-disk box beta P d^2: %s %.5f +- %.5f, event %.5f +- %.5f\n", backend.c_str(), mc.mean, mc.error,
                md.mean, md.error);
    expect_agree(md, mc, backend + " backend wall pressure beta P d^2");
}

// The course's and the suites' `metropolis` backend (sampling/metropolis_sampler.h) in the same
// box: its wall pressure is the density of centres at contact with a wall, extrapolated by its
// own parabola over 5 % of sigma, per unit wall length, times sigma^2: the fourth route of this box.
TEST(FourDiskBox, TheMetropolisBackendGivesEventsWallPressure) {
    expect_events_wall_pressure("metropolis", [](RunSettings& run) { run.sweeps = 2'000'000; });
}

// `ecmc` (sampling/ecmc_sampler.h) in the same box, its chains turned back at the walls: its
// wall pressure comes from the lifts, a turn at a wall counting as a lift to the disk's mirror
// image, over the whole box's area (docs/monte-carlo.md, "Walls"): the fifth route.
TEST(FourDiskBox, TheEcmcBackendGivesEventsWallPressure) {
    expect_events_wall_pressure("ecmc", [](RunSettings& run) { run.chains = 400'000; });
}

}  // namespace
}  // namespace collide::test
