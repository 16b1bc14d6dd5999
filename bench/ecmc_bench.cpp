// Benchmark suite `ecmc`: event-chain Monte Carlo (`ecmc`) against event-driven dynamics
// (`event`) on the scenes of Li et al. 2022: N = 870 in the crystal box (29 x 30) at eta 0.670
// and 0.698, and N = 10^4 (100 x 100) at 0.70. Per run and backend: events (lifts or
// collisions) per processor second, the pressure beta P d^2 with its batch-means error, and the
// figure of merit error^2 x processor seconds (smaller is better: the variance of the mean
// falls as 1 / seconds, so the product is the variance one processor second buys).
//
// Each run starts from the lattice, equilibrates (not timed), then hands its configuration to a
// fresh solver that is timed. Three runs (seeds 1, 2, 3); the medians are held to the targets
// of issue "A second route": >= 1e7 lifts/s on one core at N = 870 and 10^4, and a figure of
// merit at least 2x better than the published ECMC code's at N = 870, eta 0.670 (+-0.0025 in
// 31 s on this machine: 6.25e-6 x 31 = 1.9e-4, so the target is <= 9.7e-5).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "bench_suite.h"
#include "crystal_box.h"
#include "core/backend_registry.h"
#include "core/numerics/median.h"
#include "core/scene/scene_loader.h"
#include "core/thermo/pressure_record.h"

namespace collide::bench {
namespace {

constexpr double lifts_per_second_target = 1e7;
constexpr double published_figure_of_merit = 0.0025 * 0.0025 * 31;  // HistoricDisks straight ECMC, N = 870, eta 0.670
constexpr int bench_runs = 3;

struct BenchScene {
    int columns, rows;
    double eta;
    bool fom_target;  // the published code's figure of merit was measured here
};

struct Measurement {
    double events = 0, cpu_seconds = 0, beta_pressure = 0, error = 0;
    double events_per_second() const { return events / cpu_seconds; }
    double figure_of_merit() const { return error * error * cpu_seconds; }
};

// ecmc runs exactly t chains by advance_to(t): chains = duration = a number it never reaches.
Scene sampler_scene(Scene s) {
    s.run.duration = s.run.output_interval = 1e15;
    s.run.chains = 1'000'000'000'000'000;
    return s;
}

// Chains until `lifts` more lifts are done. The sampler's stats() works out the pressure's
// batch means each time it is read, so it is read only a few times (reading it every 200
// chains cost up to a third of the timed part): the chains still needed are predicted from the
// lifts per chain so far, and a last short stretch makes up any shortfall.
void run_lifts(Solver& sampler, std::int64_t lifts) {
    const std::int64_t start = sampler.stats().contacts;
    const double first_chain = sampler.time();
    double chains = first_chain + 200;
    sampler.advance_to(chains);
    for (std::int64_t done; (done = sampler.stats().contacts - start) < lifts;) {
        const double lifts_per_chain = double(std::max<std::int64_t>(done, 1)) / (chains - first_chain);
        chains += std::max(1.0, std::ceil(double(lifts - done) / lifts_per_chain));
        sampler.advance_to(chains);
    }
}

Measurement measure_ecmc(const Scene& scene, std::int64_t equilibrate, std::int64_t measure) {
    const Scene s = sampler_scene(scene);
    ParticleState<double> state = generate_initial_state(s);
    auto warm = find_backend("ecmc").create(BackendOptions{});
    warm->load(s, state);
    run_lifts(*warm, equilibrate);
    warm->read_state(state);
    auto sampler = find_backend("ecmc").create(BackendOptions{});
    sampler->load(s, state);
    Measurement m;
    const double start = cpu_seconds();
    run_lifts(*sampler, measure);
    m.cpu_seconds = cpu_seconds() - start;
    const SolverStats stats = sampler->stats();
    m.events = double(stats.contacts);
    m.beta_pressure = stats.counters.at("beta_pressure");
    m.error = stats.counters.at("beta_pressure_error");
    return m;
}

// event: the pressure record of every event run (core/thermo/pressure_record.h), sampled once per
// window of about N / 2 collisions after the equilibration.
Measurement measure_event(const Scene& scene, std::int64_t equilibrate, std::int64_t measure) {
    Scene s = scene;
    s.run.duration = 1e9;
    ParticleState<double> state = generate_initial_state(s);
    auto solver = find_backend("event").create(BackendOptions{});
    solver->load(s, state);
    // Collisions per unit time, from a short first stretch, size the windows.
    solver->advance_to(1.0);
    const double rate = double(std::max<std::int64_t>(1, solver->stats().contacts));
    const double window = 0.5 * double(state.size()) / rate;
    while (solver->stats().contacts < equilibrate) solver->advance_to(solver->time() + window);
    solver->read_state(state);
    PressureRecorder record(s, state, window);
    record.sample(solver->stats(), solver->time());
    Measurement m;
    const std::int64_t start_collisions = solver->stats().contacts;
    const double start = cpu_seconds();
    while (solver->stats().contacts - start_collisions < measure) {
        solver->advance_to(solver->time() + window);
        record.sample(solver->stats(), solver->time());
    }
    m.cpu_seconds = cpu_seconds() - start;
    m.events = double(solver->stats().contacts - start_collisions);
    const auto counters = record.counters();
    m.beta_pressure = counters.at("beta_pressure");
    m.error = counters.at("beta_pressure_error");
    return m;
}

std::string scene_label(const BenchScene& b) {
    char text[64];
    std::snprintf(text, sizeof text, "N = %d, eta %.3f", b.columns * b.rows, b.eta);
    return text;
}

void add_median_rows(const BenchScene& b, const std::string& backend, const std::vector<Measurement>& runs,
                     BenchReport& report, bool quick) {
    std::vector<double> rate, fom, p, err;
    for (const Measurement& m : runs) {
        rate.push_back(m.events_per_second());
        fom.push_back(m.figure_of_merit());
        p.push_back(m.beta_pressure);
        err.push_back(m.error);
    }
    const double r = median(rate), f = median(fom);
    const bool ecmc = backend == "ecmc";
    const std::string judged = quick ? "not judged (--quick)" : "";
    const std::string rate_target = ecmc ? ">= 1e7 lifts/s" : "";
    const std::string rate_met = !ecmc ? "" : !judged.empty() ? judged : r >= lifts_per_second_target ? "yes" : "no";
    const double fom_target = 0.5 * published_figure_of_merit;
    const std::string fom_met = !(ecmc && b.fom_target) ? "" : !judged.empty() ? judged : f <= fom_target ? "yes" : "no";
    report.add({{"scene", scene_label(b)}, {"backend", backend}, {"run", std::string("median")},
                {"events_per_s", r}, {"events_per_s_target", rate_target}, {"events_per_s_met", rate_met},
                {"beta_pressure", median(p)}, {"error", median(err)}, {"figure_of_merit", f},
                {"figure_of_merit_target", ecmc && b.fom_target ? "<= " + std::to_string(fom_target) : std::string()},
                {"figure_of_merit_met", fom_met}});
}

void run_ecmc_suite(const BenchArgs& args, BenchReport& report) {
    const std::vector<BenchScene> scenes = {{29, 30, 0.670, true}, {29, 30, 0.698, false}, {100, 100, 0.70, false}};
    const double scale = args.quick ? 0.05 : 1.0;
    report.note("figure of merit: beta_pressure_error^2 x processor seconds of the timed part; the published code's "
                "(HistoricDisks straight ECMC, N = 870, eta 0.670): 0.0025^2 x 31 s = 1.9e-4, target half of it");
    const int backends = int(wanted(args, "ecmc")) + int(wanted(args, "event"));  // the progress line's total
    report.expect_work(double(bench_runs * scenes.size() * backends));
    for (const BenchScene& b : scenes) {
        const std::int64_t n = std::int64_t(b.columns) * b.rows;
        std::vector<Measurement> ecmc_runs, event_runs;
        for (int run = 1; run <= bench_runs; ++run) {
            const Scene scene = crystal_box(b.columns, b.rows, b.eta, std::uint64_t(run));
            for (const std::string backend : {"ecmc", "event"}) {
                if (!wanted(args, backend)) continue;
                const Measurement m = backend == "ecmc"
                                          ? measure_ecmc(scene, std::int64_t(scale * 5e3 * n), std::int64_t(scale * 6e7))
                                          : measure_event(scene, std::int64_t(scale * 300 * n), std::int64_t(scale * 6e6));
                (backend == "ecmc" ? ecmc_runs : event_runs).push_back(m);
                report.add({{"scene", scene_label(b)}, {"backend", backend}, {"run", std::int64_t(run)},
                            {"events_per_s", m.events_per_second()}, {"beta_pressure", m.beta_pressure},
                            {"error", m.error}, {"cpu_seconds", m.cpu_seconds}, {"figure_of_merit", m.figure_of_merit()}});
                report.work_done(1, scene_label(b) + ", " + backend + ", run " + std::to_string(run));
            }
        }
        if (!ecmc_runs.empty()) add_median_rows(b, "ecmc", ecmc_runs, report, args.quick);
        if (!event_runs.empty()) add_median_rows(b, "event", event_runs, report, args.quick);
    }
}

}  // namespace

BenchSuite ecmc_bench_suite() {
    return {"ecmc", "event-chain Monte Carlo vs event: lifts/s and figure of merit (error^2 x CPU s), N = 870 at eta 0.670/0.698 "
                    "and N = 1e4 at 0.70, median of 3 runs against the targets",
            run_ecmc_suite};
}

}  // namespace collide::bench
