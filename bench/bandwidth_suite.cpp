// Suite `bandwidth`: how close the `cpu` backend comes to this machine's memory bandwidth.
//   1. A STREAM triad a[i] = b[i] + s c[i] (McCalpin's STREAM benchmark; 24 bytes per i
//      counted, as STREAM does) on arrays much larger than the last-level cache, at 1 thread
//      and at all threads, best of several repetitions.
//   2. The bytes the cpu backend must move per particle-step (the model below).
//   3. bound = bandwidth / bytes per particle-step, against the measured throughput of the
//      benchmark gas with all threads: the fraction of the bound reached.
#include <omp.h>

#include <algorithm>
#include <cmath>
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
// c = cells per particle.
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
double cpu_bytes_per_particle_step(double cells_per_particle) {
    return 12 + 12 + 8 + 40 + 20 + 16 + 36 + 16 + (16 + 4) * cells_per_particle;
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
    // Cells of edge 2 r_max = 1 over the box (the grid's rule).
    const double cells = std::floor(gas.scene.world.width()) * std::floor(gas.scene.world.height());
    const double bytes = cpu_bytes_per_particle_step(cells / double(particles));
    BackendOptions options;
    options.threads = all;
    const FrameTiming t = measure_frames(find_backend("cpu"), options, gas, args.quick ? 40 : args.steps, 1e9);
    const double bound = bandwidth / bytes;
    Row row{{"measure", "cpu"}, {"bytes_per_particle_step", bytes}, {"triad_gb_per_s", bandwidth / 1e9},
            {"bound_particle_steps_per_s", bound}, {"fraction_of_bound", t.particle_steps_per_second / bound},
            {"working_set_mib", bytes * double(particles) / (1 << 20)}};
    add_timing(row, t, particles);
    report.add(row);
    report.note("bytes per particle-step is a model of compulsory traffic (bench/bandwidth_suite.cpp); "
                "a working set below the last-level cache size can run above the DRAM bound");
}

}  // namespace collide::bench
