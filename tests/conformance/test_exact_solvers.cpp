// The two exact solvers against each other: `event` (reference/event/event_solver.*, tuned for
// speed) and `event-plain` (reference/plain_event_solver.*, written to be read). Both solve
// the same dynamics with the same formulas (physics/collision_time.h, collision_rule.h) but
// with their own event loops, queues and cell lists, so a bug in either shows as a difference.
//
// The bound. On few-body scenes the two find the same events in the same order and differ only
// by rounding: the tuned solver moves a disk from its clock at its own events and predicts
// only the disks an event touches, the plain one re-predicts after every cell crossing and
// breaks ties of equal times in its own order. Both write positions from the same expressions,
// so the trajectories agree to a few units in the last place; the test allows 1e-9, relative
// to the size of the coordinate or velocity (at least 1). This holds until the first
// near-grazing collision (one whose impact parameter is within rounding of the contact
// distance): there the two may disagree on whether the disks touch at all, and after it the
// trajectories part. None of the cases here has one. In a gas, chaos amplifies the rounding
// differences tenfold every 2 to 3 collisions per disk (tests/reference/test_event_brute_force.cpp
// measures it), so gases are compared by their statistics: pressure and collision rate, within
// error bars from the spread over time windows.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "conformance.h"
#include "core/metrics.h"
#include "core/scene/scene_loader.h"
#include "core/numerics/state_hash.h"
#include "tests/support/state_difference.h"
#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

std::unique_ptr<Solver> make(const std::string& backend) { return find_backend(backend).create(BackendOptions{}); }

// Runs both exact solvers side by side and compares their states at every output time.
void expect_same_trajectories(const std::string& name, const Scene& scene, const ParticleState<double>& initial) {
    for (const char* backend : {"event", "event-plain"})
        if (auto reason = find_backend(backend).supports(scene)) {
            std::printf("%s: left out, %s does not support it: %s\n", name.c_str(), backend, reason->c_str());
            return;
        }
    auto event = make("event"), plain = make("event-plain");
    event->load(scene, initial);
    plain->load(scene, initial);
    ParticleState<double> a, b;
    StateDifference worst;
    for (double t : output_times(scene)) {
        event->advance_to(t);
        plain->advance_to(t);
        event->read_state(a);
        plain->read_state(b);
        const StateDifference d = state_difference(scene, a, b, true);
        worst.position = std::max(worst.position, d.position);
        worst.velocity = std::max(worst.velocity, d.velocity);
        ASSERT_LT(d.position, 1e-9) << name << " at t = " << t;
        ASSERT_LT(d.velocity, 1e-9) << name << " at t = " << t;
    }
    const SolverStats se = event->stats(), sp = plain->stats();
    EXPECT_EQ(se.contacts, sp.contacts) << name;
    EXPECT_EQ(se.counters.at("events_wall"), sp.counters.at("events_wall")) << name;
    std::printf("%s: %lld collisions; largest relative difference: positions %.1e, velocities %.1e\n", name.c_str(),
                static_cast<long long>(se.contacts), worst.position, worst.velocity);
}

TEST(ExactSolvers, SameTrajectoriesOnEveryConformanceCase) {
    for (const ConformanceCase& c : conformance_cases()) expect_same_trajectories(c.name, c.scene, c.initial);
}

TEST(ExactSolvers, SameTrajectoriesOnLibraryFewBodyScenes) {
    for (const char* file : {"glancing.toml", "head_on_equal.toml", "head_on_mass_ratio_10.toml",
                             "stiff/newtons_cradle.toml", "stiff/pi_billiard_k3.toml", "stiff/mass_ratio_head_on.toml",
                             "stiff/exactly_touching.toml"}) {
        const Scene scene = load_scene(scene_file(file));
        expect_same_trajectories(file, scene, generate_initial_state(scene));
    }
}

// Acceptance: the plain solver conserves the kinetic energy of the 1000-disk box to rounding.
TEST(ExactSolvers, PlainSolverConservesEnergyInTheThousandDiskBox) {
    const Scene scene = load_scene(scene_file("box_gas_1000.toml"));
    const auto initial = generate_initial_state(scene);
    auto plain = make("event-plain");
    const RunResult r = run_scene(scene, *plain, initial);
    const Metrics &a = r.series.front(), &b = r.series.back();
    EXPECT_GT(r.stats.contacts, 10000);
    EXPECT_NEAR(b.kinetic_energy, a.kinetic_energy, 1e-12 * a.kinetic_energy);
    EXPECT_EQ(b.overlapping_pairs, 0);
    EXPECT_LE(b.max_wall_penetration, 1e-12);
}

// Both refuse the same bad starts with the same message (reference/hard_disk_input.h).
TEST(ExactSolvers, BothRefuseTheSameBadStarts) {
    const Scene box = box_scene(10, 10);
    struct Bad {
        ParticleState<double> state;
        std::string message;
    };
    const Bad bad[] = {
        {make_state({{2, 2, 0, 0, 0.5, 1}, {5, 5, 0, 0, 0.5, 1}, {5.6, 5, 0, 0, 0.5, 1}}), "particles 1 and 2 overlap by 0.4"},
        {make_state({{0.2, 5, 0, 0, 0.5, 1}}), "reaches outside the walls"},
        {make_state({{5, 5, 0, 0, 0.0, 1}}), "hard disks need a radius > 0"},
    };
    for (const char* backend : {"event", "event-plain"})
        for (const Bad& b : bad) {
            try {
                make(backend)->load(box, b.state);
                ADD_FAILURE() << backend << " accepted a start it should refuse (" << b.message << ")";
            } catch (const std::runtime_error& e) {
                const std::string what = e.what();
                EXPECT_EQ(what.rfind(std::string(backend) + ": ", 0), 0u) << what;
                EXPECT_NE(what.find(b.message), std::string::npos) << what;
            }
        }
}

// Per time window: collision rate (collisions per disk per unit time) and pressure, from the
// differences of the solver's counters over the window (the same formulas as its stats()).
struct Window {
    double rate, pressure;
};

Window window(const Scene& scene, std::size_t n, const SolverStats& from, const SolverStats& to, double length) {
    auto delta = [&](const char* key) { return to.counters.at(key) - from.counters.at(key); };
    const World& w = scene.world;
    const double area = w.width() * w.height();
    const double rate = 2 * double(to.contacts - from.contacts) / (double(n) * length);
    if (scene.periodic())  // virial theorem: P A = <K> + sum d.(J n) / (2 t)
        return {rate, (delta("kinetic_integral") / length + delta("virial_sum") / (2 * length)) / area};
    return {rate, delta("wall_impulse") / (2 * (w.width() + w.height()) * length)};
}

struct Estimate {
    double mean = 0, error = 0;  // mean over windows and its standard error
};

Estimate estimate(const std::vector<double>& v) {
    Estimate e;
    for (double x : v) e.mean += x / double(v.size());
    double var = 0;
    for (double x : v) var += (x - e.mean) * (x - e.mean) / double(v.size() - 1);
    e.error = std::sqrt(var / double(v.size()));
    return e;
}

// Both solvers on a 1000-disk gas for 4 times the scene's duration (some 100 collisions per
// disk: the trajectories part after about 30), in 20 windows. The window means of pressure and
// collision rate must agree within 4 combined standard errors (a bound that treats the two
// runs as independent, which overstates the error early on, where they still agree closely).
void expect_same_statistics(const std::string& file) {
    Scene scene = load_scene(scene_file(file));
    const auto initial = generate_initial_state(scene);
    const int windows = 20;
    const double length = 4 * scene.run.duration / windows;
    std::map<std::string, std::vector<double>> rate, pressure;
    for (const char* backend : {"event", "event-plain"}) {
        auto solver = make(backend);
        solver->load(scene, initial);
        SolverStats before = solver->stats();
        for (int k = 1; k <= windows; ++k) {
            solver->advance_to(k * length);
            const SolverStats after = solver->stats();
            const Window w = window(scene, initial.size(), before, after, length);
            rate[backend].push_back(w.rate);
            pressure[backend].push_back(w.pressure);
            before = after;
        }
    }
    for (auto* quantity : {&rate, &pressure}) {
        const Estimate a = estimate((*quantity)["event"]), b = estimate((*quantity)["event-plain"]);
        const double bound = 4 * std::hypot(a.error, b.error);
        const char* what = quantity == &rate ? "collision rate" : "pressure";
        std::printf("%s, %s: event %.5f +- %.5f, event-plain %.5f +- %.5f\n", file.c_str(), what, a.mean, a.error,
                    b.mean, b.error);
        EXPECT_GT(a.error, 0) << what;
        EXPECT_LE(std::fabs(a.mean - b.mean), bound) << file << ", " << what;
    }
}

TEST(ExactSolvers, SamePressureAndCollisionRateInTheThousandDiskBox) { expect_same_statistics("box_gas_1000.toml"); }
TEST(ExactSolvers, SamePressureAndCollisionRateInThePeriodicGas) { expect_same_statistics("periodic_gas.toml"); }

// Golden end-of-run state hashes (core/numerics/state_hash.h: the exact bits of every position and
// velocity), Box2D v3's test_determinism style: any change to the arithmetic of a solver, the
// order of its events or the scene generators changes a hash. The values hold for IEEE double
// arithmetic without fused multiply-add (the build's x86-64 flags); a change that alters them
// on purpose (a new formula) updates them here and says why in its commit. On the few-body
// scene the two exact solvers give the same bits; in a gas their rounding differs (see above).
struct Golden {
    const char* backend;
    const char* scene;
    std::uint64_t hash;
};

TEST(GoldenStateHash, EndOfRunStatesOfTheSerialDoubleBackends) {
    const Golden golden[] = {
        {"event", "glancing.toml", 0x206e73c173aec225ull},
        {"event-plain", "glancing.toml", 0x206e73c173aec225ull},
        {"step", "glancing.toml", 0xd8d5ea265d5352abull},
        {"event", "stones_and_gas.toml", 0x908de63a411f3a20ull},
        {"event-plain", "stones_and_gas.toml", 0x1f273ac9909e2245ull},
        {"step", "stones_and_gas.toml", 0xc9248b37f1c61bc1ull},
        {"event", "periodic_gas.toml", 0x094168e927fdd6a8ull},
        {"event-plain", "periodic_gas.toml", 0x2139bfca57eab8f3ull},
        {"step", "head_on_mass_ratio_10.toml", 0x2cd8ec5390fdcabdull},
    };
    for (const Golden& g : golden) {
        const Scene scene = load_scene(scene_file(g.scene));
        auto solver = make(g.backend);
        const RunResult r = run_scene(scene, *solver, generate_initial_state(scene));
        const std::uint64_t hash = state_hash(r.final_state);
        EXPECT_EQ(hash, g.hash) << g.backend << " on " << g.scene << ": 0x" << std::hex << hash;
    }
}

}  // namespace
}  // namespace collide::test
