// Suite `bandwidth`: how close the `cpu` backend comes to this machine's memory bandwidth.
//   1. A STREAM triad a[i] = b[i] + s c[i] (McCalpin's STREAM benchmark; 24 bytes per i
//      counted, as STREAM does) on arrays much larger than the last-level cache, at 1 thread
//      and at all threads, best of several repetitions.
//   2. The bytes the cpu backend must move per particle-step (the model below).
//   3. bound = bandwidth / bytes per particle-step, against the measured throughput of the
//      benchmark gas with all threads: the fraction of the bound reached.
//   4. The compute ceiling: the same gas, small enough that its whole working set stays in the
//      caches, on one thread (best of 5 windows), times the thread count. No DRAM traffic limits
//      it, so it is the fastest the code can go on this machine; the large run's fraction of it
//      says how much of the large run's time memory (and imperfect scaling) costs, and a
//      ceiling below the bound says that the bound is out of reach of this code whatever its
//      memory traffic.
//   5. The target, fraction_of_bound >= 0.6 at N = 1e6 on two threads, with the verdict.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame_timing.h"

namespace collide::bench {

namespace {

// Best triad bandwidth in bytes per second over `reps` repetitions.
double triad_bandwidth(std::size_t n, int threads, int reps) {
    std::vector<double> a(n), b(n), c(n);
    const auto count = std::int64_t(n);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < count; ++i) a[i] = 0, b[i] = 1, c[i] = 2;  // first touch by the same threads
    double best = 0;
    for (int r = 0; r < reps; ++r) {
        const double scalar = 3.0 + r;
        const double seconds = time_seconds([&] {
#pragma omp parallel for schedule(static) num_threads(threads)
            for (std::int64_t i = 0; i < count; ++i) a[i] = b[i] + scalar * c[i];
        });
        best = std::max(best, 24.0 * double(n) / seconds);
    }
    if (a[n / 2] != 1 + (3.0 + reps - 1) * 2) best = -1;  // keeps the loop from being optimised away
    return best;
}

}  // namespace

// Bytes the cpu backend moves per particle-step for the benchmark gas (collide-first, equal
// radii and masses, no stones, reorder by cell at every grid build: the default), counting
// each array element read or written once per pass (4-byte floats and indices) and assuming
// the neighbours' data is found in cache (the reorder by cell is what makes that true).
// c = cells per particle, p = pairs in the list per particle, k = steps per list build.
//
// The cell path (skin 0), every step:
//   grid:     cell of each disk (read x, y; write cell)                 12
//             count (read cell, update a counter)                       12
//             scatter: read cell, update the slot counter               8
//             and move x, y, vx, vy and the scene index into cell order 40
//             (equal radii and masses are not moved)
//             zero the histogram, prefix sum, write the cell starts     16 c
//   contacts: read x, y, vx, vy, inv_mass                               20
//             write dx, dy, dvx, dvy                                    16
//             read the starts of 3 rows of cells                        4 c (each start read ~once)
//   update:   read x, y, vx, vy, radius, dx, dy, dvx, dvy               36
//             write x, y, vx, vy                                        16
// The pair list (the default), every step:
//   stale?:   read x, y and the positions at the build                  16
//   contacts: read the pairs, and x, y (the partner's in cache)         8 p + 8
//   update:   as above                                                  52
// and every k-th step the grid as above (72 + 16 c), then the list: read x, y and the row
// starts (8 + 4 c), write each chunk's pairs (8 p; the chunks are the list), save x, y (16).
struct TrafficModel {
    double cells_per_particle = 0;
    bool listed = false;            // the pair list (else the cell path)
    double pairs_per_particle = 0;
    double steps_per_build = 1;
};

double cpu_bytes_per_particle_step(const TrafficModel& m) {
    const double c = m.cells_per_particle, p = m.pairs_per_particle;
    const double grid = 12 + 12 + 8 + 40 + 16 * c, update = 36 + 16;
    if (!m.listed) return grid + 20 + 16 + 4 * c + update;
    const double build = grid + 8 + 4 * c + 8 * p + 16;
    return 16 + 8 * p + 8 + update + build / m.steps_per_build;
}

// The model's inputs from a run: the grid's cells (the solver's own count, whatever the skin
// it ran with) and, for the pair list, the list's length and builds over the measured frames.
TrafficModel traffic_of(const GasCase& gas, const FrameTiming& t, int frames) {
    const double n = double(gas.initial.size());
    auto counter = [&](const std::map<std::string, double>& counters, const char* name) {
        const auto found = counters.find(name);
        return found != counters.end() ? found->second : -1.0;
    };
    const double cells = counter(t.counters, "grid_cells"), pairs = counter(t.counters, "pair_list_pairs");
    if (cells < 0) throw std::runtime_error("bench bandwidth: the cpu run reported no grid_cells counter");
    TrafficModel m;
    m.cells_per_particle = cells / n;
    if (pairs >= 0) {
        m.listed = true;
        m.pairs_per_particle = pairs / n;
        m.steps_per_build = double(frames) / std::max(1.0, counter(t.counters_gained, "pair_list_builds"));
    }
    return m;
}

void run_bandwidth_suite(const BenchArgs& args, BenchReport& report) {
    // 3 x 128 MiB arrays (3 x 32 MiB with --quick, which may sit in a large last-level cache).
    const std::size_t n = args.quick ? (std::size_t(1) << 22) : (std::size_t(1) << 24);
    const int reps = args.quick ? 3 : 8;
    const int all = args.threads.empty() ? omp_get_max_threads() : args.threads.back();
    double bandwidth = 0;
    for (int threads : {1, all}) {
        const double bw = triad_bandwidth(n, threads, reps);
        report.add({{"measure", "triad"}, {"threads", std::int64_t(threads)}, {"array_mib", double(n) * 8 / (1 << 20)},
                    {"gb_per_s", bw / 1e9}});
        bandwidth = std::max(bandwidth, bw);
    }

    const std::int64_t particles = !args.sizes.empty() ? args.sizes.back() : args.quick ? 100000 : 1000000;
    const GasCase gas = bench_gas(particles);
    BackendOptions options;
    options.threads = all;
    const int frames = args.quick ? 40 : args.steps;
    const FrameTiming t = measure_frames(find_backend("cpu"), options, gas, frames, 1e9);
    const TrafficModel traffic = traffic_of(gas, t, frames);
    const double bytes = cpu_bytes_per_particle_step(traffic);
    const double bound = bandwidth / bytes;

    // The compute ceiling: one thread on N = 1e4 (a working set of about 2 MiB, in the
    // caches), times the thread count: what the threads would give if memory cost nothing and
    // they scaled perfectly. One thread, because on a shared machine a small step on several
    // threads waits at every barrier for a thread another job has taken off its core (runs of
    // 2e4 disks on two threads came out slower per particle-step than 1e6). As many
    // particle-steps as the large run (at most 1e8: a few seconds) in 5 windows, the best of
    // which counts: a ceiling is what the code reaches when the machine lets it (the triad,
    // too, is a best of several).
    const std::int64_t small = std::min<std::int64_t>(particles, 10000);
    const GasCase small_gas = bench_gas(small);
    const double large_work = double(particles) * (args.quick ? 40 : args.steps);
    const int windows = 5;
    const int window_steps = int(std::max(40.0, std::min(large_work, 1e8) / double(small) / windows));
    BackendOptions one_thread = options;
    one_thread.threads = 1;
    FrameTiming c;
    for (int w = 0; w < windows; ++w) {
        const FrameTiming window = measure_frames(find_backend("cpu"), one_thread, small_gas, window_steps, 1e9);
        if (window.particle_steps_per_second > c.particle_steps_per_second) c = window;
    }
    const double ceiling = c.particle_steps_per_second * all;
    Row ceiling_row{{"measure", "cpu_in_cache"}, {"working_set_mib", bytes * double(small) / (1 << 20)},
                    {"compute_ceiling_particle_steps_per_s", ceiling}, {"fraction_of_bound", ceiling / bound}};
    add_timing(ceiling_row, c, small);
    report.add(ceiling_row);

    const double fraction = t.particle_steps_per_second / bound;
    Row row{{"measure", "cpu"}, {"bytes_per_particle_step", bytes}, {"triad_gb_per_s", bandwidth / 1e9},
            {"pairs_per_particle", traffic.pairs_per_particle}, {"steps_per_list_build", traffic.steps_per_build},
            {"bound_particle_steps_per_s", bound}, {"fraction_of_bound", fraction},
            {"compute_ceiling_particle_steps_per_s", ceiling},
            {"fraction_of_compute_ceiling", t.particle_steps_per_second / ceiling},
            {"working_set_mib", bytes * double(particles) / (1 << 20)}};
    add_timing(row, t, particles);
    report.add(row);
    report.note("bytes per particle-step is a model of compulsory traffic (bench/bandwidth_suite.cpp); "
                "a working set below the last-level cache size can run above the DRAM bound");
    report.note("cpu_in_cache is the same gas at N = " + std::to_string(small) +
                " on one thread, whose working set stays in the caches, best of " + std::to_string(windows) +
                " windows; compute_ceiling = " + std::to_string(all) +
                " x its rate (perfect scaling). Its fraction_of_bound is the most the large run could reach if "
                "memory cost nothing");
    char verdict[256];
    const bool configured = particles == 1000000 && all == 2;
    std::snprintf(verdict, sizeof verdict, "target: fraction_of_bound >= 0.6 at N = 1e6, 2 threads \u2014 measured %.3f%s \u2014 %s",
                  fraction, configured ? "" : (" (at N = " + std::to_string(particles) + ", " + std::to_string(all) +
                                                " threads)").c_str(),
                  !configured ? "not the target's configuration" : fraction >= 0.6 ? "met" : "not met");
    report.note(verdict);
}

}  // namespace collide::bench
