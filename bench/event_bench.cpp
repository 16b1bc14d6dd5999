// Benchmark suite `event`: throughput of the two event-driven solvers, `event` (tuned) and
// `event-plain` (the plain one a student reads), one thread, in collisions per second and
// nanoseconds per collision, for N = 1e3 ... 1e6 disks at area fractions 0.1, 0.5 and 0.7 in a
// periodic box. Flat cost per collision in N is the point of the cell list and the event
// queue; the table shows it directly, and cost_vs_event says how many times slower the plain
// solver is than the tuned one on the same gas.
//
// Placement: random sequential addition cannot reach area fraction 0.7 (it jams near 0.55),
// so every case starts from a square lattice (which holds up to pi/4 = 0.785) with random
// velocities and is "melted" by running it for a few collisions per disk before timing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <random>
#include <vector>
#include <string>

#include "bench_suite.h"
#include "core/scene/gas_scene.h"
#include "core/numerics/median.h"
#include "core/backend_registry.h"

namespace collide::bench {
namespace {

// n unit-mass disks of radius 1/2 on a square lattice in a periodic square box whose size
// gives the requested area fraction phi = n pi r^2 / L^2; velocity components Gaussian with
// unit variance (kT/m = 1), the centre-of-mass motion removed (core/scene/gas_scene.h).
GasCase lattice_gas(std::int64_t n, double area_fraction, std::uint64_t seed) {
    GasSceneSpec spec;
    spec.count = n;
    spec.area_fraction = area_fraction;
    spec.seed = seed;
    spec.boundary = Boundary::periodic;
    spec.placement = GasPlacement::lattice;
    spec.remove_drift = true;
    GasCase gas = make_gas(spec);
    gas.scene.name = "event_bench";
    return gas;
}

struct Timing {
    double seconds = 0;      // wall clock
    double cpu_seconds = 0;  // processor time
};

// Advances the solver until at least `target` more collisions have happened, in steps of
// simulated time sized from the collision rate seen so far. Returns the steps' wall-clock and
// processor time.
Timing run_collisions(Solver& solver, std::int64_t target) {
    const std::int64_t start = solver.stats().contacts;
    double step = 0.01;
    Timing timing;
    while (solver.stats().contacts - start < target) {
        const std::int64_t before = solver.stats().contacts;
        const double t = solver.time() + step;
        const double cpu_before = cpu_seconds();
        timing.seconds += time_seconds([&] { solver.advance_to(t); });
        timing.cpu_seconds += cpu_seconds() - cpu_before;
        const std::int64_t done = solver.stats().contacts - before;
        // Aim for about 20 steps per measurement.
        const std::int64_t want = std::max<std::int64_t>(1, target / 20);
        step *= done > 0 ? std::clamp(double(want) / double(done), 0.5, 4.0) : 4.0;
    }
    return timing;
}

// The timed part is split into this many windows of equal collision count; the table gives
// the median time per collision over the windows and its range, so that the noise of the
// machine (other programs, a shared cache) is visible next to the figure.
constexpr int timing_windows = 5;


// One solver at one size and area fraction: melted, and what its timing windows measured.
struct SizeCase {
    std::string backend;
    std::int64_t n = 0;
    std::unique_ptr<Solver> solver;
    std::int64_t per_window = 0;  // collisions per timing window
    double melt_seconds = 0;
    SolverStats before;           // the solver's counters when timing began
    Timing timing;                // summed over the windows
    std::vector<double> window_ns;  // ns per collision in each window
};

SizeCase melted_case(const std::string& backend, std::int64_t n, double phi, bool quick) {
    SizeCase c;
    c.backend = backend;
    c.n = n;
    const std::int64_t melt = quick ? n : 5 * n;
    const std::int64_t measured = std::max<std::int64_t>(quick ? 100000 : 1000000, 5 * n);
    c.per_window = measured / timing_windows;
    std::fprintf(stderr, "[%s] N = %lld, area fraction %.1f: melting (%lld collisions)...\n", backend.c_str(),
                 static_cast<long long>(n), phi, static_cast<long long>(melt));
    GasCase gas = lattice_gas(n, phi, 42);
    c.solver = find_backend(backend).create(BackendOptions{});
    c.solver->load(gas.scene, gas.initial);
    // Melt the lattice: a few collisions per disk forget the initial order.
    c.melt_seconds = run_collisions(*c.solver, melt).seconds;
    c.before = c.solver->stats();
    return c;
}

// Times the windows of all sizes and solvers in turn (window 1 of every case, then window 2,
// ...), so that a machine whose speed drifts over minutes (other programs, frequency changes)
// affects every case alike, and the ratio of two cases can be taken window by window.
void time_interleaved(std::vector<SizeCase>& cases, double phi, BenchReport& report) {
    double planned = 0;
    for (const SizeCase& c : cases) planned += double(c.per_window) * timing_windows;
    report.expect_work(planned);
    for (int w = 0; w < timing_windows; ++w)
        for (SizeCase& c : cases) {
            const std::int64_t start = c.solver->stats().contacts;
            const Timing t = run_collisions(*c.solver, c.per_window);
            c.timing.seconds += t.seconds;
            c.timing.cpu_seconds += t.cpu_seconds;
            c.window_ns.push_back(1e9 * t.seconds / double(c.solver->stats().contacts - start));
            char what[128];
            std::snprintf(what, sizeof what, "area fraction %.1f, timing window %d of %d: N = %lld (%s, %lld collisions)", phi,
                          w + 1, timing_windows, static_cast<long long>(c.n), c.backend.c_str(),
                          static_cast<long long>(c.per_window));
            report.work_done(double(c.per_window), what);
        }
}

// Median over the windows of a's ns per collision over b's in the same round, and the range.
struct Ratio {
    double median, min, max;
};
Ratio window_ratio(const SizeCase& a, const SizeCase& b) {
    std::vector<double> ratios;
    for (std::size_t w = 0; w < a.window_ns.size(); ++w) ratios.push_back(a.window_ns[w] / b.window_ns[w]);
    return {median(ratios), *std::min_element(ratios.begin(), ratios.end()), *std::max_element(ratios.begin(), ratios.end())};
}

// smallest: the same solver at the smallest N; event: the tuned solver at the same N.
void report_case(const SizeCase& c, const SizeCase& smallest, const SizeCase& event, double phi, BenchReport& report) {
    const SolverStats after = c.solver->stats();
    const double collisions = double(after.contacts - c.before.contacts);
    const double events = double(after.steps - c.before.steps);
    const double stale = after.counters.at("events_stale") - c.before.counters.at("events_stale");
    const double ns = median(c.window_ns);
    const Ratio vs_smallest = window_ratio(c, smallest), vs_event = window_ratio(c, event);
    Row row = {{"backend", c.backend},
               {"threads", std::int64_t(1)},
               {"n", c.n},
               {"area_fraction", phi},
               {"collisions", std::int64_t(collisions)},
               {"seconds", c.timing.seconds},
               {"melt_seconds", c.melt_seconds},
               {"collisions_per_second", 1e9 / ns},
               {"ns_per_collision", ns},
               {"ns_per_collision_min", *std::min_element(c.window_ns.begin(), c.window_ns.end())},
               {"ns_per_collision_max", *std::max_element(c.window_ns.begin(), c.window_ns.end())},
               {"cost_vs_smallest_n", vs_smallest.median},
               {"cost_vs_smallest_n_min", vs_smallest.min},
               {"cost_vs_smallest_n_max", vs_smallest.max},
               {"cost_vs_event", vs_event.median},
               {"cost_vs_event_min", vs_event.min},
               {"cost_vs_event_max", vs_event.max},
               {"cpu_seconds", c.timing.cpu_seconds},
               {"cpu_ns_per_collision", 1e9 * c.timing.cpu_seconds / collisions},
               {"events_per_collision", events / collisions},
               {"stale_per_collision", stale / collisions}};
    // Where the solver prefetches (from 2^16 disks on): the share of events (stale ones
    // included) whose disk, or either disk of a collision, the calendar's look-ahead had named
    // ahead (docs/event-driven.md, "Prefetching the coming events").
    if (after.counters.count("events_named_ahead")) {
        const double named = after.counters.at("events_named_ahead") - c.before.counters.at("events_named_ahead");
        row["named_ahead_per_event"] = named / (events + stale);
    }
    report.add(row);
}

// Issue 39's targets for `event` (one core, periodic lattice gas melted as above): the
// throughput at N = 1e5 (area fraction 0.5: 2e6 collisions/s, 0.1: 1e6; none at 0.7) and the
// growth of the cost per collision from N = 1e3 to 1e6 (at most 1.3x, every area fraction).
double throughput_target(double phi) {
    if (std::fabs(phi - 0.5) < 1e-9) return 2e6;
    if (std::fabs(phi - 0.1) < 1e-9) return 1e6;
    return 0;
}
constexpr double cost_growth_target = 1.3;

std::string number_text(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}
// A rate as the tables of the journal write it: 1.12e6, 2e6.
std::string rate_text(double value) {
    const int exponent = value > 0 ? int(std::floor(std::log10(value))) : 0;
    return number_text("%.3g", value / std::pow(10.0, exponent)) + "e" + std::to_string(exponent);
}

// One line per target of `event` at this area fraction: "target: ... measured: ... met/not
// met". `event_cases` are the tuned solver's cases, smallest N first. A target whose size was
// not run says so instead of judging another size.
void report_targets(const std::vector<const SizeCase*>& event_cases, double phi, BenchReport& report) {
    const std::string where = "event, area fraction " + number_text("%.1f", phi) + ": ";
    if (const double target = throughput_target(phi); target > 0) {
        const std::string line = where + "target: >= " + rate_text(target) + " collisions/s at N = 1e5; measured: ";
        auto at_1e5 = std::find_if(event_cases.begin(), event_cases.end(), [](const SizeCase* c) { return c->n == 100000; });
        if (at_1e5 == event_cases.end()) report.note(line + "N = 1e5 not run");
        else {
            const double measured = 1e9 / median((*at_1e5)->window_ns);
            report.note(line + rate_text(measured) + " collisions/s; " + (measured >= target ? "met" : "not met"));
        }
    }
    const SizeCase& smallest = *event_cases.front();
    const SizeCase& largest = *event_cases.back();
    std::string line = where + "target: cost per collision from N = 1e3 to 1e6 within " +
                       number_text("%.1f", cost_growth_target) + "x; measured: ";
    if (smallest.n != 1000 || largest.n != 1000000) {
        const double growth = window_ratio(largest, smallest).median;
        report.note(line + number_text("%.2f", growth) + "x from N = " + std::to_string(smallest.n) + " to " +
                    std::to_string(largest.n) + " (not the target's sizes: not judged)");
        return;
    }
    const double growth = window_ratio(largest, smallest).median;
    report.note(line + number_text("%.2f", growth) + "x; " + (growth <= cost_growth_target ? "met" : "not met"));
}

void run_event_suite(const BenchArgs& args, BenchReport& report) {
    if (!wanted(args, "event")) return;
    std::vector<std::int64_t> sizes = args.sizes;
    if (sizes.empty()) sizes = args.quick ? std::vector<std::int64_t>{1000, 10000}
                                          : std::vector<std::int64_t>{1000, 10000, 100000, 1000000};
    std::sort(sizes.begin(), sizes.end());  // the ratio column is relative to the smallest N
    // `event` always runs (the other solver's cost_vs_event is relative to it); `event-plain`
    // unless --backend names only `event`.
    std::vector<std::string> solvers = {"event"};
    if (args.backends.empty() || wanted(args, "event-plain")) solvers.push_back("event-plain");
    for (double phi : {0.1, 0.5, 0.7}) {
        std::vector<SizeCase> cases;  // size by size, each size's solvers in `solvers` order
        for (std::int64_t n : sizes)
            for (const std::string& backend : solvers) cases.push_back(melted_case(backend, n, phi, args.quick));
        time_interleaved(cases, phi, report);
        std::vector<const SizeCase*> event_cases;
        for (std::size_t k = 0; k < cases.size(); ++k) {
            report_case(cases[k], cases[k % solvers.size()], cases[k - k % solvers.size()], phi, report);
            if (k % solvers.size() == 0) event_cases.push_back(&cases[k]);
        }
        report_targets(event_cases, phi, report);
    }
    report.note("ns_per_collision is the median over " + std::to_string(timing_windows) +
                " equal windows of the timed collisions (wall clock), with the windows' range in "
                "ns_per_collision_min/max; collisions_per_second = 1e9 / ns_per_collision. cpu_ns_per_collision "
                "uses the process's processor time over all windows (steadier on a loaded machine). "
                "The windows of all sizes of one area fraction are timed in turn (window 1 of each size, then "
                "window 2, ...); cost_vs_smallest_n is the median over the windows of this size's ns per collision "
                "over the smallest size's in the same round, with its range in cost_vs_smallest_n_min/max, "
                "per solver; cost_vs_event is the same for this solver over `event` at the same N (how many times "
                "slower the plain solver is). The targets of `event` (issue 39) are judged above, per area fraction, "
                "on the wall-clock medians.");
}

}  // namespace

BenchSuite event_bench_suite() {
    return {"event", "event-driven solvers (event, event-plain): collisions/s and ns/collision, 1 thread, N = 1e3..1e6, "
                     "area fraction 0.1/0.5/0.7",
            run_event_suite};
}

}  // namespace collide::bench
