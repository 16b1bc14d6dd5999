// parallel_for: the one way the `cpu` backend runs a loop over particles in parallel.
//
// A persistent worker pool over about four chunks of the particle range per worker, each worker
// taking one contiguous run of chunks (`schedule(static)`); workloads too small to pay for the
// hand-off run inline on the calling thread. OpenMP provides this: the runtime keeps its threads
// alive between parallel regions (the persistent pool). A loop of the same length gets the same
// disks on the same worker in every region and every step, so each worker finds the disks it
// wrote in the last phase in its own cache, and the workers' ranges meet at one boundary each
// instead of at every chunk. Two earlier choices, measured (bench/journal.md): chunks claimed
// from a shared cursor (`schedule(dynamic, 1)`) sent the data between the cores' caches at
// every phase; chunks dealt in turn (`schedule(static, 1)`) kept it but put a boundary between
// the workers at every chunk (where, we take it, both cores write the same cache lines), and
// two threads stayed slower than one at N = 10^4 (4.1-8.2 against 3.9-4.0 ns per disk-step);
// contiguous runs give 3.0-3.2 ns there on two quiet cores. What is given up is the balance of
// a dense region spread over several workers' chunks: a dense half of the box now falls to one
// worker.
//
// The body receives a half-open range [begin, end) so that its inner loop is a plain loop the
// compiler can vectorise, and returns a count (contacts found, or 0) that is summed over
// chunks. Integer sums do not depend on the order of addition, so the total is the same for
// every thread count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace collide::cpu {

// Below this many items a loop runs inline on the calling thread: waking the pool costs a
// few microseconds, about the time a single thread needs for this many particles.
inline constexpr std::size_t kInlineBelow = 4096;
// Chunks smaller than this cost more in hand-offs than they save in balance.
inline constexpr std::size_t kMinChunk = 1024;
// About four chunks per worker, each worker taking its chunks as one contiguous run. The pair
// list builds one buffer per chunk of rows with the same count, so in cell order its chunks
// roughly line up with the workers' ranges of disks.
inline constexpr std::size_t kChunksPerThread = 4;

// The chunks a loop over [0, n) is cut into: about kChunksPerThread per worker, none smaller
// than min_chunk items.
struct ChunkPlan {
    std::size_t n, chunk;
    std::int64_t count;
    ChunkPlan(std::size_t items, int threads, std::size_t min_chunk) : n(items) {
        const std::size_t workers = std::size_t(std::max(threads, 1));
        chunk = std::max<std::size_t>(1, std::max(min_chunk, (n + kChunksPerThread * workers - 1) / (kChunksPerThread * workers)));
        count = std::int64_t((n + chunk - 1) / chunk);
    }
    // Runs body(begin, end) on chunk c and returns its count.
    template <typename Body>
    std::int64_t run(std::int64_t c, Body& body) const {
        const std::size_t begin = std::size_t(c) * chunk;
        return body(begin, std::min(n, begin + chunk));
    }
};

// Whether a loop over `particles` particles is worth waking the pool for. Inline, outside any
// OpenMP region: even a region of one thread (`if (false)`) costs a team set-up per call,
// microseconds that a two-disk scene pays every step.
inline bool runs_inline(int threads, std::size_t particles) { return threads <= 1 || particles < kInlineBelow; }

// Runs body over [0, n) in chunks. `particles` is the number of particles the loop covers,
// which decides whether it is worth waking the pool (by default the items are particles);
// `min_chunk` is the smallest chunk handed out (in items).
template <typename Body>
std::int64_t parallel_for(std::size_t n, int threads, Body&& body, std::size_t particles, std::size_t min_chunk) {
    const ChunkPlan plan(n, threads, min_chunk);
    std::int64_t total = 0;
    if (runs_inline(threads, particles)) {
        for (std::int64_t c = 0; c < plan.count; ++c) total += plan.run(c, body);
        return total;
    }
#pragma omp parallel for schedule(static) num_threads(threads) reduction(+ : total)
    for (std::int64_t c = 0; c < plan.count; ++c) total += plan.run(c, body);
    return total;
}

// A test over [0, n_test) and, only when its total is zero (the test passed), work over
// [0, n_work), in one parallel region: the threads meet at the barrier that ends the test's loop,
// where its total is summed, and go on to the work or leave together. One hand-off to the pool
// instead of two (about 1.2 µs each on two cores: bench/journal.md), for a test that nearly
// always passes (the pair list's stale test before its contact search). Each loop is cut as
// parallel_for cuts it. Returns the test's total.
template <typename Test, typename Work>
std::int64_t parallel_test_then_work(std::size_t n_test, Test&& test, std::size_t n_work, std::size_t work_min_chunk,
                                     Work&& work, int threads, std::size_t particles) {
    const ChunkPlan test_plan(n_test, threads, kMinChunk), work_plan(n_work, threads, work_min_chunk);
    std::int64_t failed = 0;
    if (runs_inline(threads, particles)) {
        for (std::int64_t c = 0; c < test_plan.count; ++c) failed += test_plan.run(c, test);
        if (failed == 0)
            for (std::int64_t c = 0; c < work_plan.count; ++c) work_plan.run(c, work);
        return failed;
    }
#pragma omp parallel num_threads(threads)
    {
#pragma omp for schedule(static) reduction(+ : failed)
        for (std::int64_t c = 0; c < test_plan.count; ++c) failed += test_plan.run(c, test);
        // The loop's implicit barrier has summed `failed` for every thread.
        if (failed == 0) {
#pragma omp for schedule(static)
            for (std::int64_t c = 0; c < work_plan.count; ++c) work_plan.run(c, work);
        }
    }
    return failed;
}

template <typename Body>
std::int64_t parallel_for(std::size_t n, int threads, Body&& body) {
    return parallel_for(n, threads, body, n, kMinChunk);
}

}  // namespace collide::cpu
