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
// list builds one buffer per chunk of rows with the same count, so its chunks line up with the
// workers' ranges of disks (in cell order).
inline constexpr std::size_t kChunksPerThread = 4;

// Runs body over [0, n) in chunks. `particles` is the number of particles the loop covers,
// which decides whether it is worth waking the pool (by default the items are particles);
// `min_chunk` is the smallest chunk handed out (in items).
template <typename Body>
std::int64_t parallel_for(std::size_t n, int threads, Body&& body, std::size_t particles, std::size_t min_chunk) {
    const std::size_t workers = std::size_t(std::max(threads, 1));
    const std::size_t chunk = std::max(min_chunk, (n + kChunksPerThread * workers - 1) / (kChunksPerThread * workers));
    const std::int64_t chunks = std::int64_t((n + chunk - 1) / chunk);
    auto run_chunk = [&](std::int64_t c) {
        const std::size_t begin = std::size_t(c) * chunk;
        return body(begin, std::min(n, begin + chunk));
    };
    std::int64_t total = 0;
    if (workers == 1 || particles < kInlineBelow) {
        // Inline, outside any OpenMP region: even a region of one thread (`if (false)`) costs
        // a team set-up per call, microseconds that a two-disk scene pays every step.
        for (std::int64_t c = 0; c < chunks; ++c) total += run_chunk(c);
        return total;
    }
#pragma omp parallel for schedule(static) num_threads(threads) reduction(+ : total)
    for (std::int64_t c = 0; c < chunks; ++c) total += run_chunk(c);
    return total;
}

template <typename Body>
std::int64_t parallel_for(std::size_t n, int threads, Body&& body) {
    return parallel_for(n, threads, body, n, kMinChunk);
}

}  // namespace collide::cpu
