// The optimised `event` backend (reference/event/event_solver.h: cell list with crossings, calendar
// queue, renumbering, prefetching, a clock per disk) against the plain one, `event-plain`
// (reference/plain_event_solver.cpp: a binary heap of every predicted event, lazy invalidation,
// a plain cell list), in gases of a few dozen disks. The two must find the same collisions in
// the same order, so the collision counts agree exactly and the states agree to rounding,
// amplified by the chaos of the hard-disk gas. (This file once held a naive O(N^2)-per-event
// solver of its own; there is now one plain solver, the backend, and the conformance tests
// hold the two against each other on every shared case as well.)
//
// What the comparisons cover of the optimised solver: cell crossings (also through periodic
// sides), pair and wall predictions from per-disk clocks, the crossing shortcut (only the three
// entered cells are searched), stale queue entries, and the renumbering at load (disks are
// numbered in cell order inside the solver, and read_state must map them back to the scene's
// order). The renumbering repeated every 4 N + 1000 events needs more events than a comparison
// can run before chaos takes over (see expect_same_run), so the comparisons are also run with
// the option renumber_interval = 7, which renumbers dozens of times within them; and a later
// test checks that renumbering changes no bit of a long run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/numerics/number_text.h"
#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "reference/event/event_solver.h"
#include "reference/plain_event_solver.h"
#include "tests/support/state_difference.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

constexpr double never = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------
// Initial states
// ---------------------------------------------------------------------------------------

struct Species {
    double radius, mass;
};

struct Gas {
    Scene scene;
    ParticleState<double> initial;
};

// columns x rows disks in a box that a square lattice of the given spacing fills exactly, one
// disk per lattice cell, each of a species drawn at random. Each centre is displaced from its
// cell's centre by up to spacing/2 - r along each axis, so every disk lies inside its own
// cell: the cells do not overlap, hence neither do the disks, and none reaches past a wall.
// Velocities are uniform in [-1, 1]^2. The spacing must exceed the largest diameter.
Gas lattice_gas(Boundary boundary, int columns, int rows, double spacing, const std::vector<Species>& species,
                std::uint64_t seed) {
    Gas gas{test::box_scene(columns * spacing, rows * spacing, boundary), {}};
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::size_t> pick(0, species.size() - 1);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<test::DiskSpec> disks;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const Species& s = species[pick(rng)];
            const double play = 0.5 * spacing - s.radius;
            const double x = (column + 0.5) * spacing + play * unit(rng);
            const double y = (row + 0.5) * spacing + play * unit(rng);
            disks.push_back({x, y, unit(rng), unit(rng), s.radius, s.mass});
        }
    gas.initial = test::make_state(disks);
    return gas;
}

// The lattice spacing that gives area fraction phi when the species are equally likely.
double spacing_for(double phi, const std::vector<Species>& species) {
    double mean_area = 0;
    for (const auto& s : species) mean_area += std::numbers::pi * s.radius * s.radius / double(species.size());
    return std::sqrt(mean_area / phi);
}

double area_fraction(const Gas& gas) {
    double area = 0;
    for (double r : gas.initial.radius) area += std::numbers::pi * r * r;
    return area / (gas.scene.world.width() * gas.scene.world.height());
}

// ---------------------------------------------------------------------------------------
// Comparing the two solvers
// ---------------------------------------------------------------------------------------

// Runs both solvers from the same start to t_end and checks that they agree.
//
// Why 1e-9 is a safe bound, and what limits the run length. Both solvers find the same
// events with the same formulas, but round differently: the plain one moves a disk from its
// clock at each of its events, cell crossings included, while the optimised one predicts only
// the three entered cells after a crossing and orders equal times its own way. So after the
// first events the states differ by a few units in the last place of the coordinates (~1e-15
// for coordinates ~10). Hard-disk dynamics is chaotic: at a collision, an error delta in where
// two disks touch turns their velocities by an angle of order delta / sigma, which the next free
// flight of length l turns into a position error of about (l / sigma) delta. So errors grow by
// a roughly constant factor per collision of a disk, i.e. exponentially in time. Measured
// (against a naive solver that moved every disk at every event, which rounds more): the largest
// difference grows about tenfold per 2 to 3 collisions per disk, from ~1e-14 after one
// collision per disk to 1e-12..1e-11 after 6 to 8 and 1e-9 after 10 to 16; in the bidisperse box
// it reaches the size of the velocities after ~30 collisions per disk, and then the collision
// counts part. The runs below stop after 6 to 8 collisions per disk (the largest difference is
// printed when the test runs). A real discrepancy (a missed or mistimed collision, a wrong
// impulse) shows up at once as a difference of order the disk size or the speed, and usually
// as a different collision count.
// options: the event solver's [backend.event] options (renumber_interval, cell_size).
using Options = std::map<std::string, std::string>;
void expect_same_run(const Gas& gas, double t_end, const char* label, const Options& options = {}) {
    Scene scene = gas.scene;
    for (const auto& [key, value] : options) scene.backend_options["event"][key] = value;
    EventSolver fast;
    fast.load(scene, gas.initial);
    fast.advance_to(t_end);
    ParticleState<double> fast_state;
    fast.read_state(fast_state);
    const SolverStats stats = fast.stats();

    PlainEventSolver plain;
    plain.load(gas.scene, gas.initial);
    plain.advance_to(t_end);
    ParticleState<double> plain_state;
    plain.read_state(plain_state);
    const SolverStats plain_stats = plain.stats();
    const auto plain_walls = static_cast<std::int64_t>(plain_stats.counters.at("events_wall"));

    // (The counts could differ by one if an event fell within rounding of t_end, one solver
    // processing it and the other not; with ~1e3 events per time unit that has a chance of
    // ~1e-12 per run, and the end times below are fixed.)
    const test::StateDifference d = test::state_difference(gas.scene, fast_state, plain_state, false);
    const auto cell_crossings = static_cast<long long>(stats.counters.at("events_cell"));
    const auto shell_exits = static_cast<long long>(stats.counters.at("events_shell"));
    std::printf("%s: N = %zu, area fraction %.3f, t = %g: %lld pair and %lld wall collisions (%lld cell crossings "
                "and %lld shell exits in the event solver); max |dx| = %.2e, max |dv| = %.2e\n",
                label, gas.initial.size(), area_fraction(gas), t_end, static_cast<long long>(plain_stats.contacts),
                static_cast<long long>(plain_walls), cell_crossings, shell_exits, d.position, d.velocity);

    // The comparison must have exercised what it is meant to: disks moved between cells (or,
    // with neighbour lists, rebuilt them at shell exits, and never crossed a cell) and, in a
    // box with walls, hit the walls.
    if (options.contains("shell")) {
        EXPECT_GT(shell_exits, 0);
        EXPECT_EQ(cell_crossings, 0);
    } else {
        EXPECT_GT(cell_crossings, 0);
        EXPECT_EQ(shell_exits, 0);
    }
    if (!gas.scene.periodic()) {
        EXPECT_GT(plain_walls, 0);
    }
    EXPECT_EQ(stats.contacts, plain_stats.contacts);
    EXPECT_EQ(static_cast<std::int64_t>(stats.counters.at("events_wall")), plain_walls);
    EXPECT_LT(d.position, 1e-9);
    EXPECT_LT(d.velocity, 1e-9);
}

// ---------------------------------------------------------------------------------------
// Tests
// ---------------------------------------------------------------------------------------

TEST(EventBruteForce, PeriodicEqualDisksMatchPlainSolver) {
    // 64 disks of radius 0.5 at area fraction 0.45: minimum image across the sides and cell
    // crossings through them.
    const std::vector<Species> equal = {{0.5, 1.0}};
    const Gas gas = lattice_gas(Boundary::periodic, 8, 8, spacing_for(0.45, equal), equal, 2024);
    expect_same_run(gas, 2.5, "periodic");
    expect_same_run(gas, 2.5, "periodic, renumbered every 7 events", {{"renumber_interval", "7"}});
    // Cells of any edge >= 2 r_max hold every partner in the 3x3 around a disk: 2.6 (4 x 4
    // cells) finds the same collisions with fewer crossings.
    expect_same_run(gas, 2.5, "periodic, cells of 2.6", {{"cell_size", "2.6"}});
    // Neighbour lists with shells (reference/event/neighbour_shells.h): the same collisions,
    // through the periodic sides too, for a thin and a thick shell, and with the lists renamed
    // at every renumbering.
    expect_same_run(gas, 2.5, "periodic, shells of 0.1", {{"shell", "0.1"}});
    expect_same_run(gas, 2.5, "periodic, shells of 0.3, renumbered every 7 events",
                    {{"shell", "0.3"}, {"renumber_interval", "7"}});
}

TEST(EventBruteForce, ReflectingBidisperseUnequalMassesMatchPlainSolver) {
    // 70 disks of two radii (0.35 and 0.5) with unequal masses in a box with walls: wall
    // events, cell crossings and the mass-weighted collision rule all take part. The masses
    // are not proportional to the areas, so a rule that ignored them (or used the wrong one)
    // would change the velocities.
    const std::vector<Species> two = {{0.35, 1.0}, {0.5, 3.5}};
    const Gas gas = lattice_gas(Boundary::reflect, 10, 7, spacing_for(0.45, two), two, 77);
    expect_same_run(gas, 1.5, "reflecting, bidisperse");
    expect_same_run(gas, 1.5, "reflecting, bidisperse, renumbered every 7 events", {{"renumber_interval", "7"}});
    expect_same_run(gas, 1.5, "reflecting, bidisperse, cells of 1.7", {{"cell_size", "1.7"}});
    expect_same_run(gas, 1.5, "reflecting, bidisperse, shells of 0.25", {{"shell", "0.25"}});
}

// The state (in the scene's order) and the collision count of the event solver at time t.
std::pair<ParticleState<double>, std::int64_t> final_state(const Gas& gas, double t, const Options& options) {
    Scene scene = gas.scene;
    for (const auto& [key, value] : options) scene.backend_options["event"][key] = value;
    EventSolver solver;
    solver.load(scene, gas.initial);
    solver.advance_to(t);
    ParticleState<double> state;
    solver.read_state(state);
    return {state, solver.stats().contacts};
}

// One entry of the event solver's provenance (event.cells, event.prefetch, ...) for a scene
// loaded with the given [backend.event] options.
std::string provenance_entry(Scene scene, const ParticleState<double>& initial, const Options& options,
                             const std::string& key) {
    for (const auto& [option, value] : options) scene.backend_options["event"][option] = value;
    EventSolver solver;
    solver.load(scene, initial);
    return solver.provenance().at(key);
}

// Positions and velocities equal to the last bit (no tolerance).
void expect_bitwise_equal(const ParticleState<double>& state, const ParticleState<double>& reference,
                          const std::string& what) {
    ASSERT_EQ(state.size(), reference.size()) << what;
    for (std::size_t i = 0; i < state.size(); ++i) {
        ASSERT_EQ(state.x[i], reference.x[i]) << "disk " << i << ", " << what;
        ASSERT_EQ(state.y[i], reference.y[i]) << "disk " << i << ", " << what;
        ASSERT_EQ(state.vx[i], reference.vx[i]) << "disk " << i << ", " << what;
        ASSERT_EQ(state.vy[i], reference.vy[i]) << "disk " << i << ", " << what;
    }
}

// A dilute bidisperse gas (area fraction 0.08: cells of 2 r_max would hold 0.1 disk on average)
// in the cells `event` chooses for it: edge 0.45 (a^2 / d)^(1/3), a the area per disk and d the
// mean diameter (EventSolver::load), here about 1.8 of the larger diameters, where one disk per
// cell would be 2.7 (30 x 30 cells against 20 x 20; with the largest diameter for d, 31 x 31:
// the two radii tell the mean diameter from the largest one). The grid expected is computed
// from that formula, and the run must find the plain solver's collisions.
TEST(EventBruteForce, DiluteGasInItsOwnCellsMatchesPlainSolver) {
    const std::vector<Species> two = {{0.35, 1.0}, {0.5, 1.0}};
    const double spacing = spacing_for(0.08, two);
    const Gas gas = lattice_gas(Boundary::periodic, 20, 20, spacing, two, 31);
    double radius_sum = 0;
    for (double r : gas.initial.radius) radius_sum += r;
    const double area_per_disk = spacing * spacing, diameter = 2 * radius_sum / double(gas.initial.size());
    const double edge = 0.45 * std::cbrt(area_per_disk * area_per_disk / diameter);
    const std::string cells = std::to_string(std::int64_t(std::floor(20 * spacing / edge)));
    EXPECT_EQ(provenance_entry(gas.scene, gas.initial, {}, "event.cells"), cells + "x" + cells);
    expect_same_run(gas, 7.0, "periodic, dilute, the solver's own cells");

    // A small box of 25 disks at area fraction 0.001: the balance asks for cells of 1.37
    // sqrt(a), too wide for four per axis, so the cells hold one disk's share each (5 x 5),
    // not the 140 x 140 of 2 r_max.
    const std::vector<Species> equal = {{0.5, 1.0}};
    const Gas sparse = lattice_gas(Boundary::periodic, 5, 5, spacing_for(0.001, equal), equal, 31);
    EXPECT_EQ(provenance_entry(sparse.scene, sparse.initial, {}, "event.cells"), "5x5");
}

// Renumbering the disks in cell order (for memory locality) must not change the run at all:
// it moves records without touching a number, each cell keeps its order of visits, and the
// calendar breaks ties by the scene's index. So a long run gives the same state to the last
// bit whether the solver renumbers every 7 events, every 13, or at its default interval
// (about 4 N events). Exact equality, no tolerance: one differently rounded collision time
// would grow, through the chaos of the gas, into a visible difference long before the end.
// (Equal event times do not occur in this random gas, so what this catches is a record,
// prediction or calendar entry left behind or renamed wrongly; the order of simultaneous
// events is tested by the Newton's cradle in tests/conformance. Leaving the partners of
// the predictions unrenamed, for one, fails this test and both comparisons above.)
TEST(EventBruteForce, RenumberingChangesNoBit) {
    const std::vector<Species> two = {{0.4, 1.0}, {0.5, 2.0}};
    const Gas gas = lattice_gas(Boundary::periodic, 15, 14, spacing_for(0.55, two), two, 5);
    const auto [reference, collisions] = final_state(gas, 40.0, {});
    ASSERT_GT(collisions, 20000);  // long enough that chaos would show any difference
    for (const std::string interval : {"7", "13"}) {
        const auto [state, count] = final_state(gas, 40.0, {{"renumber_interval", interval}});
        EXPECT_EQ(count, collisions) << "renumber_interval " << interval;
        expect_bitwise_equal(state, reference, "renumber_interval " + interval);
    }
}

// Prefetching the coming events (reference/event/prefetch_pipeline.h) only requests memory: forced
// on in a small periodic gas (with renumbering every 7 events, which resets the look-ahead),
// in a reflecting box (whose edge cells are not prefetched), in a dilute gas in cells of one
// disk and in its own dilute cells, and left to "auto" above its threshold, the state is the
// same to the last bit as with prefetching off.
TEST(EventBruteForce, PrefetchingChangesNoBit) {
    const std::vector<Species> two = {{0.4, 1.0}, {0.5, 2.0}};
    struct Case {
        Gas gas;
        double t;
        Options options;
    };
    const std::vector<Case> cases = {
        {lattice_gas(Boundary::periodic, 15, 14, spacing_for(0.55, two), two, 5), 40.0,
         {{"prefetch", "on"}, {"renumber_interval", "7"}}},
        {lattice_gas(Boundary::reflect, 20, 15, spacing_for(0.5, two), two, 5), 20.0, {{"prefetch", "on"}}},
        // (a dilute gas in cells of one disk on average, the lattice spacing: the pipeline's
        // stage 3 runs)
        {lattice_gas(Boundary::periodic, 40, 40, spacing_for(0.1, two), two, 5), 60.0,
         {{"prefetch", "on"}, {"cell_size", round_trip_text(spacing_for(0.1, two))}}},
        // (the same gas in the solver's own dilute cells, about 0.4 disk each: stage 3 off)
        {lattice_gas(Boundary::periodic, 40, 40, spacing_for(0.1, two), two, 5), 60.0, {{"prefetch", "on"}}},
        {lattice_gas(Boundary::periodic, 260, 260, spacing_for(0.5, two), two, 5), 0.5, {{"prefetch", "auto"}}},
    };
    for (const Case& c : cases) {
        Options off = c.options;
        off["prefetch"] = "off";
        const auto [reference, collisions] = final_state(c.gas, c.t, off);
        ASSERT_GT(collisions, 10000);
        const auto [state, count] = final_state(c.gas, c.t, c.options);
        EXPECT_EQ(count, collisions) << c.gas.initial.size() << " disks";
        expect_bitwise_equal(state, reference, std::to_string(state.size()) + " disks");
    }
    // The automatic choice does prefetch at the last case's size (else it would compare
    // "off" with "off"), and does not in the small gas; the dilute gas in cells of one disk
    // runs stage 3 of the pipeline (the second records), the same gas in its own cells and the
    // denser ones do not.
    const auto prefetching = [&](const Case& c, const std::string& choice) {
        Options options = c.options;
        options["prefetch"] = choice;
        return provenance_entry(c.gas.scene, c.gas.initial, options, "event.prefetch");
    };
    EXPECT_EQ(prefetching(cases[4], "auto"), "on") << cases[4].gas.initial.size() << " disks";
    EXPECT_EQ(prefetching(cases[0], "auto"), "off") << cases[0].gas.initial.size() << " disks";
    EXPECT_EQ(prefetching(cases[2], "on"), "on, second records");
    EXPECT_EQ(prefetching(cases[3], "on"), "on");
    EXPECT_EQ(prefetching(cases[0], "on"), "on");
}

// The look-ahead names the disk of nearly every coming event (statistic events_named_ahead),
// at each density. It passes over the partners of collisions already named: about half the
// collisions were predicted by both disks, and the second entry vanishes when the first is
// served. Without that, the front of the calendar gains on the walk, which then leaves
// entries unnamed: 94, 91 and 89 % of the events here against 98, 98 and 97 % with it.
TEST(EventPrefetch, LookAheadNamesNearlyEveryEvent) {
    const std::vector<Species> one = {{0.5, 1.0}};
    struct Case {
        double phi, t, at_least;
    };
    for (const Case& c : {Case{0.1, 40.0, 0.96}, Case{0.5, 8.0, 0.95}, Case{0.7, 4.0, 0.95}}) {
        Gas gas = lattice_gas(Boundary::periodic, 60, 50, spacing_for(c.phi, one), one, 11);
        gas.scene.backend_options["event"]["prefetch"] = "on";
        EventSolver solver;
        solver.load(gas.scene, gas.initial);
        solver.advance_to(c.t);
        const auto counters = solver.stats().counters;
        const double events = counters.at("events_pair") + counters.at("events_wall") + counters.at("events_cell") +
                              counters.at("events_stale");
        ASSERT_GT(events, 50000) << "area fraction " << c.phi;
        const double named = counters.at("events_named_ahead") / events;
        EXPECT_GE(named, c.at_least) << "area fraction " << c.phi << ": " << events << " events";
        std::printf("area fraction %.1f: %.0f events, %.4f named ahead\n", c.phi, events, named);
    }
    // Without prefetching there is no look-ahead and no such statistic.
    Gas gas = lattice_gas(Boundary::periodic, 60, 50, spacing_for(0.5, one), one, 11);
    gas.scene.backend_options["event"]["prefetch"] = "off";
    EventSolver solver;
    solver.load(gas.scene, gas.initial);
    solver.advance_to(0.1);
    EXPECT_EQ(solver.stats().counters.count("events_named_ahead"), 0u);
}

// A long, dense run with the optimised solver alone: a collision it missed would let two disks
// pass into each other, and a missed wall event would let a disk leave the box. Both are looked
// for by brute force over all pairs and all disks at many output times. Two disks passing
// through each other overlap for the time their centres need to cross the chord of the contact
// circle: with looks every 0.1 diameters of travel, only
// a miss grazing to within about a per cent of the contact distance could fall between two
// looks, and a systematic error (a cell never searched, a wrong border) would miss head-on
// collisions too.
void expect_long_dense_run_without_overlaps(const Options& options) {
    const std::vector<Species> two = {{0.4, 1.0}, {0.5, 2.0}};
    Gas gas = lattice_gas(Boundary::reflect, 20, 15, spacing_for(0.6, two), two, 5);
    for (const auto& [key, value] : options) gas.scene.backend_options["event"][key] = value;
    const Scene& scene = gas.scene;
    const World& w = scene.world;
    EventSolver solver;
    solver.load(scene, gas.initial);

    // Between two looks: the time a disk needs to travel 0.1 of the mean diameter at the
    // initial rms speed (equipartition between the two masses changes the rms speed by only a
    // few per cent).
    const std::size_t n = gas.initial.size();
    double diameter_sum = 0, v2_sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        diameter_sum += 2 * gas.initial.radius[i];
        v2_sum += gas.initial.vx[i] * gas.initial.vx[i] + gas.initial.vy[i] * gas.initial.vy[i];
    }
    const double interval = 0.1 * (diameter_sum / double(n)) / std::sqrt(v2_sum / double(n));

    const double tolerance = 1e-9;  // relative to the contact distance (pairs) or the diameter (walls)
    ParticleState<double> s;
    // The largest overlap seen (negative: the smallest gap) and the farthest reach past a wall
    // (negative: the closest approach), for the printout.
    double t = 0, worst_overlap = -never, worst_wall = -never;
    int looks = 0;
    while (solver.stats().contacts < 100000) {
        solver.advance_to(t += interval);
        solver.read_state(s);
        ++looks;
        for (std::size_t i = 0; i < s.size(); ++i) {
            const double r = s.radius[i];
            // How far the disk reaches past the nearest wall (negative: inside), per diameter.
            const double past = std::max({w.xmin - (s.x[i] - r), s.x[i] + r - w.xmax, w.ymin - (s.y[i] - r),
                                          s.y[i] + r - w.ymax}) / (2 * r);
            worst_wall = std::max(worst_wall, past);
            ASSERT_LE(past, tolerance) << "disk " << i << " outside the walls at t = " << t;
            for (std::size_t j = i + 1; j < s.size(); ++j) {
                const double sigma = r + s.radius[j];
                const double overlap = (sigma - std::hypot(s.x[i] - s.x[j], s.y[i] - s.y[j])) / sigma;
                worst_overlap = std::max(worst_overlap, overlap);
                ASSERT_LE(overlap, tolerance) << "disks " << i << " and " << j << " overlap at t = " << t;
            }
        }
    }
    std::printf("long run: N = %zu, area fraction %.3f, %lld pair and %lld wall collisions, %d looks up to t = %g; "
                "largest overlap %.2e of the contact distance, largest reach past a wall %.2e diameters "
                "(negative: the smallest gap)\n",
                s.size(), area_fraction(gas), static_cast<long long>(solver.stats().contacts),
                static_cast<long long>(solver.stats().counters.at("events_wall")), looks, t, worst_overlap, worst_wall);
}

TEST(EventBruteForce, LongDenseRunNeverOverlapsOrLeavesTheBox) { expect_long_dense_run_without_overlaps({}); }

// The same with neighbour lists (a pair left out of the lists, or a shell exit found late,
// would let two disks pass into each other), with a thin shell: many exits.
TEST(EventBruteForce, LongDenseRunWithShellsNeverOverlapsOrLeavesTheBox) {
    expect_long_dense_run_without_overlaps({{"shell", "0.05"}});
}

// Neighbour lists under renumbering and prefetching: both stay exact with shells too (the
// lists are renamed and keep their order; the pipeline's shell stages only request memory),
// so the state is the same to the last bit; and a scene under gravity keeps the cell lists
// (a parabola's shell exit would be a quartic), as does a periodic box too narrow for the
// one-shift minimum image.
TEST(EventBruteForce, ShellsRenumberedAndPrefetchedChangeNoBit) {
    const std::vector<Species> two = {{0.4, 1.0}, {0.5, 2.0}};
    const Gas gas = lattice_gas(Boundary::periodic, 15, 14, spacing_for(0.55, two), two, 5);
    const auto [reference, collisions] = final_state(gas, 40.0, {{"shell", "0.3"}, {"prefetch", "off"}});
    ASSERT_GT(collisions, 20000);
    for (const Options& options : {Options{{"shell", "0.3"}, {"renumber_interval", "7"}, {"prefetch", "off"}},
                                   Options{{"shell", "0.3"}, {"prefetch", "on"}, {"renumber_interval", "13"}}}) {
        const auto [state, count] = final_state(gas, 40.0, options);
        EXPECT_EQ(count, collisions);
        expect_bitwise_equal(state, reference, "shells with options " + options.begin()->second);
    }
    const auto neighbours = [](const Scene& scene, const ParticleState<double>& initial) {
        return provenance_entry(scene, initial, {{"shell", "0.3"}}, "event.neighbours");
    };
    EXPECT_EQ(neighbours(gas.scene, gas.initial), "shells of width 0.3");
    Scene falling = gas.scene;
    falling.world.boundary = Boundary::reflect;
    falling.physics.gravity_y = -1;
    EXPECT_EQ(neighbours(falling, gas.initial), "cells");
    const std::vector<Species> one = {{0.5, 1.0}};
    const Gas narrow = lattice_gas(Boundary::periodic, 3, 3, spacing_for(0.3, one), one, 5);
    EXPECT_EQ(neighbours(narrow.scene, narrow.initial), "cells");
}

}  // namespace
}  // namespace collide
