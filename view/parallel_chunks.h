// parallel_chunks: how the viewer shares a loop among threads (the overlap search, the quads of
// the disks, the rows of the picture). The simulation and the drawing of a frame run one after
// the other, so the drawing has the simulation's threads to itself. OpenMP keeps its threads
// alive between parallel regions (the `cpu` backend's pool, already awake), and each chunk is
// a fixed range, so results joined in chunk order do not depend on the thread count.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace collide::view {

// Below this many items a loop runs on the calling thread: waking the pool would cost more.
inline constexpr std::size_t parallel_from = 4096;
// Chunks per thread: a few, so that one slow chunk does not leave the other threads idle.
inline constexpr std::size_t chunks_per_thread = 4;

inline int thread_count(int threads) { return threads > 0 ? threads : omp_get_max_threads(); }

struct ChunkPlan {
    std::size_t items = 0, size = 1, count = 0;  // [c * size, min(items, (c + 1) * size)) is chunk c
};

// `items` cut into at most `chunks` chunks of equal size (the last one shorter).
inline ChunkPlan split_into(std::size_t items, std::size_t chunks) {
    ChunkPlan p;
    p.items = items;
    p.size = std::max<std::size_t>(1, (items + chunks - 1) / std::max<std::size_t>(1, chunks));
    p.count = (items + p.size - 1) / p.size;
    return p;
}

// A few chunks per thread, or one chunk for a loop too short to share.
inline ChunkPlan plan_chunks(std::size_t items, int threads) {
    return split_into(items, items < parallel_from ? 1 : chunks_per_thread * std::size_t(thread_count(threads)));
}

// Calls body(chunk, begin, end) once for every chunk of `plan`, on up to `threads` threads.
template <typename Body>
void parallel_chunks(const ChunkPlan& plan, int threads, Body&& body) {
    const std::int64_t count = std::int64_t(plan.count);
#pragma omp parallel for schedule(dynamic, 1) num_threads(thread_count(threads)) if (count > 1)
    for (std::int64_t c = 0; c < count; ++c) {
        const std::size_t begin = std::size_t(c) * plan.size;
        body(std::size_t(c), begin, std::min(plan.items, begin + plan.size));
    }
}

}  // namespace collide::view
