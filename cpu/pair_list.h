// PairList: the `cpu` backend's Verlet list of pairs, each pair once (docs/cpu-backend.md,
// "Pairs within reach, each tested once").
//
// The cell path (collide_range) rebuilds the grid at every step and tests, for every disk, its
// 3x3 neighbourhood: at area fraction 0.3 about 3.4 candidates per disk and each pair twice,
// once from each side. A Verlet list (Verlet, Phys. Rev. 159, 98 (1967); Allen & Tildesley,
// "Computer Simulation of Liquids", 2nd ed., §5.3) keeps instead every pair whose distance was
// below the reach r_i + r_j + skin when the list was built, and keeps it until some disk has
// moved by half the skin: until then no pair outside the list can touch, since two disks close
// in on each other by at most the sum of their displacements. Each pair is stored once (the
// lower state slot first), its distance is tested once per step, and the grid is rebuilt only
// when the list is.
//
// Each chunk of the list computes both shares of its contacts (on its thread, right after its
// search); the `cpu` solver's update then adds them, each thread those of its own disks, walking
// the contacts in list order (cpu_solver.cpp, update_with_corrections): the order of every
// per-disk sum is the order of the list, whatever the number of threads. The list itself is
// built in parallel over rows of cells into one buffer per chunk, read in chunk order: the same
// list for any thread count.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "candidate_mask.h"
#include "cpu_cell_list.h"
#include "core/particle_state.h"
#include "parallel_for.h"
#include "phase_kernels.h"

namespace collide::cpu {

// Appends pairs to a chunk's buffer without a branch on whether a candidate is kept. Whether a
// block of candidates holds a pair within reach is a branch the processor cannot predict: its
// misses were a third of the list build's time (bench/journal.md). Here every candidate is
// written at the end and the end moves past it only when it is kept, so the kept pairs come
// out in the order of the candidates, as push_back would give them.
class PairAppender {
public:
    explicit PairAppender(std::vector<DiskPair>& out) : out_(out), size_(out.size()) {}
    PairAppender(const PairAppender&) = delete;
    PairAppender& operator=(const PairAppender&) = delete;
    ~PairAppender() { out_.resize(size_); }  // the buffer ends at the last kept pair

    // Room for `count` more candidates.
    void make_room(std::size_t count) {
        if (out_.size() < size_ + count) [[unlikely]]
            out_.resize(std::max(2 * out_.size(), size_ + count));
    }
    void put(DiskPair pair, bool keep) {
        out_[size_] = pair;
        size_ += std::size_t(keep);
    }
    // The pairs (a, block + l) for the set bits l of a candidate mask (candidate_mask.h).
    void put_mask(std::uint32_t a, std::uint32_t block, unsigned mask) {
        for (unsigned l = 0; l < 4; ++l) put({a, block + l}, (mask >> l) & 1u);
    }

private:
    std::vector<DiskPair>& out_;
    std::size_t size_;
};

class PairList {
public:
    // A disk may move this fraction of the skin between builds (one half, less a margin for the
    // rounding of float positions: the list stays exact with 0.1 of the skin to spare).
    static constexpr float kMoveFraction = 0.4f;

    // Forgets the list (a new scene): the next is_stale() says true.
    void reset(float skin) {
        skin_ = skin;
        chunk_pairs_.clear();
        size_ = 0;
        x0_.clear();
        y0_.clear();
        chunk_contacts_.clear();
    }
    float skin() const { return skin_; }
    std::size_t size() const { return size_; }
    std::int64_t builds() const { return builds_; }
    // The list's chunks (contact_chunks() has one per chunk): the unit of parallel work.
    std::size_t chunks() const { return chunk_pairs_.size(); }
    // The pairs in contact found by the last search, chunk by chunk: read in chunk order, the
    // list's order.
    const std::vector<std::vector<DiskPair>>& contact_chunks() const { return chunk_contacts_; }
    // The same, as one list.
    std::vector<DiskPair> contacts() const {
        std::vector<DiskPair> all;
        for (const auto& chunk : chunk_contacts_) all.insert(all.end(), chunk.begin(), chunk.end());
        return all;
    }

    // True when the list may have missed a pair: there is none yet, or some disk has moved
    // kMoveFraction of the skin since it was built (a NaN position counts as moved).
    template <bool Periodic>
    bool is_stale(const ParticleState<float>& s, const PhaseParams& p, int threads) const;

    // Rebuilds the list from a grid just built from s's positions, with cells at least
    // 2 r_max + skin wide. InCellOrder: s is in the grid's cell order (slot k is disk k);
    // otherwise slots map to disks through grid.sorted_index().
    template <bool UniformRadius, bool Periodic, bool InCellOrder>
    void build(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p, int threads);

    // Fills contact_chunks() with the pairs whose distance is below r_a + r_b, in list order:
    // the test of the cell path (not >=, so a NaN distance counts), once per pair. Then, on the
    // same thread, calls after_chunk(c, contacts of chunk c) for each chunk.
    template <bool UniformRadius, bool Periodic, typename AfterChunk>
    void find_contacts(const ParticleState<float>& s, const PhaseParams& p, int threads, AfterChunk&& after_chunk);
    template <bool UniformRadius, bool Periodic>
    void find_contacts(const ParticleState<float>& s, const PhaseParams& p, int threads) {
        find_contacts<UniformRadius, Periodic>(s, p, threads, [](std::size_t, const std::vector<DiskPair>&) {});
    }

    // is_stale(), then find_contacts() if the list is not stale, in one parallel region (most
    // steps need no rebuild, and one hand-off to the threads costs about as much as a tenth of
    // a step at N = 10^4). Returns false, having searched nothing, when the list is stale.
    template <bool UniformRadius, bool Periodic, typename AfterChunk>
    bool search_unless_stale(const ParticleState<float>& s, const PhaseParams& p, int threads,
                             AfterChunk&& after_chunk);

private:
    template <bool UniformRadius, bool Periodic, bool InCellOrder>
    void pairs_in_rows(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p,
                       std::size_t row_begin, std::size_t row_end, std::vector<DiskPair>& out) const;
    template <bool UniformRadius>
    void pairs_in_rows_forward(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p,
                               std::size_t row_begin, std::size_t row_end, std::vector<DiskPair>& out) const;
    template <typename Body>
    static void for_each_chunk(std::size_t count, int threads, std::size_t particles, Body&& body);
    // The stale test on the disks [begin, end): how many have moved their limit.
    template <bool Periodic>
    std::int64_t moved_in(const ParticleState<float>& s, const PhaseParams& p, std::size_t begin, std::size_t end) const;
    // The contact search on chunk c of the list, into contact_chunks()[c].
    template <bool UniformRadius, bool Periodic>
    void search_chunk(const ParticleState<float>& s, const PhaseParams& p, std::size_t c);

    float skin_ = 0;
    std::int64_t builds_ = 0;
    std::size_t size_ = 0;
    std::vector<float> x0_, y0_;  // positions at the last build
    // The list, in chunks of rows of cells (kept as built: one list in chunk order, never
    // copied into one array), and each chunk's contacts of the last search.
    std::vector<std::vector<DiskPair>> chunk_pairs_, chunk_contacts_;
};

// Runs body(c) for the chunks c = 0 .. count - 1 in parallel (inline for few particles).
template <typename Body>
void PairList::for_each_chunk(std::size_t count, int threads, std::size_t particles, Body&& body) {
    parallel_for(count, threads, [&](std::size_t c0, std::size_t c1) {
        for (std::size_t c = c0; c < c1; ++c) body(c);
        return std::int64_t(0);
    }, particles, 1);
}

template <bool Periodic>
bool PairList::is_stale(const ParticleState<float>& s, const PhaseParams& p, int threads) const {
    const std::size_t n = s.size();
    if (x0_.size() != n || builds_ == 0) return true;
    const std::int64_t moved = parallel_for(n, threads, [&](std::size_t begin, std::size_t end) {
        return moved_in<Periodic>(s, p, begin, end);
    });
    return moved > 0;
}

template <bool Periodic>
std::int64_t PairList::moved_in(const ParticleState<float>& s, const PhaseParams& p, std::size_t begin,
                                std::size_t end) const {
    const float limit = kMoveFraction * skin_, limit2 = limit * limit;
    const float *x = s.x.data(), *y = s.y.data(), *x0 = x0_.data(), *y0 = y0_.data();
    std::int64_t far = 0;
    for (std::size_t i = begin; i < end; ++i) {
        // A disk that wrapped has moved by its image's distance.
        const auto [dx, dy] = separation<Periodic>(x[i], y[i], x0[i], y0[i], p);
        far += !(dx * dx + dy * dy < limit2);
    }
    return far;
}

template <bool UniformRadius, bool Periodic, bool InCellOrder>
void PairList::build(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p, int threads) {
    auto rows = [&](std::size_t row_begin, std::size_t row_end, std::vector<DiskPair>& out) {
        if constexpr (InCellOrder && !Periodic)
            pairs_in_rows_forward<UniformRadius>(s, grid, p, row_begin, row_end, out);
        else
            pairs_in_rows<UniformRadius, Periodic, InCellOrder>(s, grid, p, row_begin, row_end, out);
    };
    // Chunks of rows, each listing into its own buffer: read in chunk order they are the same
    // list whatever the number of chunks.
    const std::size_t cells_y = std::size_t(grid.cells_y());
    const std::size_t count = std::max<std::size_t>(1, std::min(cells_y, kChunksPerThread * std::size_t(std::max(threads, 1))));
    chunk_pairs_.resize(count);
    for_each_chunk(count, threads, s.size(), [&](std::size_t c) {
        chunk_pairs_[c].clear();
        rows(cells_y * c / count, cells_y * (c + 1) / count, chunk_pairs_[c]);
    });
    size_ = 0;
    for (const auto& chunk : chunk_pairs_) size_ += chunk.size();
    x0_.assign(s.x.begin(), s.x.end());
    y0_.assign(s.y.begin(), s.y.end());
    ++builds_;
}

// The pairs within reach of the disks in rows [row_begin, row_end), any order of the state: for
// every disk i each candidate j of its 3x3 neighbourhood with j > i.
template <bool UniformRadius, bool Periodic, bool InCellOrder>
void PairList::pairs_in_rows(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p,
                             std::size_t row_begin, std::size_t row_end, std::vector<DiskPair>& out) const {
    const float *x = s.x.data(), *y = s.y.data(), *radius = s.radius.data();
    const std::uint32_t* cell_start = grid.cell_start();
    const std::uint32_t* index = InCellOrder ? nullptr : grid.sorted_index();
    const std::int64_t cells_x = grid.cells_x();
    auto disk = [index](std::uint32_t slot) { return InCellOrder ? slot : index[slot]; };
    PairAppender kept(out);
    for (std::int64_t cy = std::int64_t(row_begin); cy < std::int64_t(row_end); ++cy)
        for (std::int64_t cx = 0; cx < cells_x; ++cx) {
            const std::int64_t c = cy * cells_x + cx;
            if (cell_start[c] == cell_start[c + 1]) continue;
            SlotRange ranges[6];
            const int range_count = grid.neighbour_ranges<Periodic>(cx, cy, ranges);
            for (std::uint32_t slot = cell_start[c]; slot < cell_start[c + 1]; ++slot) {
                const std::uint32_t i = disk(slot);
                const float xi = x[i], yi = y[i], ri = UniformRadius ? p.radius : radius[i];
                for (int r = 0; r < range_count; ++r) {
                    kept.make_room(ranges[r].end - ranges[r].begin);
                    for (std::uint32_t b = ranges[r].begin; b < ranges[r].end; ++b) {
                        const std::uint32_t j = disk(b);
                        const auto [sep_x, sep_y] = separation<Periodic>(xi, yi, x[j], y[j], p);
                        const float reach = ri + (UniformRadius ? ri : radius[j]) + skin_;
                        // Each pair once, from its lower slot; within reach (not >=: a NaN counts).
                        kept.put({i, j}, j > i && !(sep_x * sep_x + sep_y * sep_y >= reach * reach));
                    }
                }
            }
        }
}

// The same pairs for a state in cell order inside reflecting walls, where slot order is row
// order: the partners j > i of disk i are the later slots of its own row's three columns and the
// row above's three columns (the row below holds only earlier slots). Both ranges are tested
// four slots at a time (candidate_mask.h) against the reach: for unequal radii the query's
// radius r_i + skin makes the mask's (r_i + r_j)^2 the reach squared.
template <bool UniformRadius>
void PairList::pairs_in_rows_forward(const ParticleState<float>& s, const CellList& grid, const PhaseParams& p,
                                     std::size_t row_begin, std::size_t row_end, std::vector<DiskPair>& out) const {
    const std::uint32_t* cell_start = grid.cell_start();
    const std::int64_t cells_x = grid.cells_x();
    const float reach = p.radius + p.radius + skin_;
    CandidateQuery q{0, 0, 0, reach * reach, p.width, p.height, s.x.data(), s.y.data(),
                     UniformRadius ? nullptr : s.radius.data(), std::uint32_t(s.size())};
    PairAppender kept(out);
    for (std::int64_t cy = std::int64_t(row_begin); cy < std::int64_t(row_end); ++cy) {
        const std::uint32_t *own = grid.row_start<false>(cy), *above = grid.row_start<false>(cy + 1);
        for (std::uint32_t a = cell_start[cy * cells_x]; a < cell_start[(cy + 1) * cells_x]; ++a) {
            q.xi = s.x[a];
            q.yi = s.y[a];
            q.ri = UniformRadius ? p.radius : s.radius[a] + skin_;
            const std::int64_t cx = grid.column_of(q.xi);
            const std::int64_t lo = cx > 0 ? cx - 1 : 0, hi = cx + 2 < cells_x ? cx + 2 : cells_x;
            const std::uint32_t b0 = a + 1, e0 = own[hi], b1 = above[lo], e1 = above[hi];
            if (e0 - b0 <= 8 && e1 - b1 <= 8) [[likely]] {
                // Up to eight slots a range (nearly always): four block tests, no branch on the
                // lengths; a block past its range's end tests nothing.
                kept.make_room(16);
                kept.put_mask(a, b0, candidate_mask<UniformRadius, false>(q, b0, e0, a));
                kept.put_mask(a, b0 + 4, candidate_mask<UniformRadius, false>(q, b0 + 4, e0, a));
                kept.put_mask(a, b1, candidate_mask<UniformRadius, false>(q, b1, e1, a));
                kept.put_mask(a, b1 + 4, candidate_mask<UniformRadius, false>(q, b1 + 4, e1, a));
                continue;
            }
            for (const SlotRange range : {SlotRange{b0, e0}, SlotRange{b1, e1}})
                for (std::uint32_t block = range.begin; block < range.end; block += 4) {
                    kept.make_room(4);
                    kept.put_mask(a, block, candidate_mask<UniformRadius, false>(q, block, range.end, a));
                }
        }
    }
}

template <bool UniformRadius, bool Periodic, typename AfterChunk>
void PairList::find_contacts(const ParticleState<float>& s, const PhaseParams& p, int threads,
                             AfterChunk&& after_chunk) {
    chunk_contacts_.resize(chunk_pairs_.size());
    for_each_chunk(chunk_pairs_.size(), threads, s.size(), [&](std::size_t c) {
        search_chunk<UniformRadius, Periodic>(s, p, c);
        after_chunk(c, chunk_contacts_[c]);
    });
}

template <bool UniformRadius, bool Periodic, typename AfterChunk>
bool PairList::search_unless_stale(const ParticleState<float>& s, const PhaseParams& p, int threads,
                                   AfterChunk&& after_chunk) {
    const std::size_t n = s.size();
    if (x0_.size() != n || builds_ == 0) return false;
    chunk_contacts_.resize(chunk_pairs_.size());
    const std::int64_t moved = parallel_test_then_work(
        n, [&](std::size_t begin, std::size_t end) { return moved_in<Periodic>(s, p, begin, end); },
        chunk_pairs_.size(), 1, [&](std::size_t c0, std::size_t c1) {
            for (std::size_t c = c0; c < c1; ++c) {
                search_chunk<UniformRadius, Periodic>(s, p, c);
                after_chunk(c, chunk_contacts_[c]);
            }
            return std::int64_t(0);
        }, threads, n);
    return moved == 0;
}

template <bool UniformRadius, bool Periodic>
void PairList::search_chunk(const ParticleState<float>& s, const PhaseParams& p, std::size_t c) {
    const float *x = s.x.data(), *y = s.y.data(), *radius = s.radius.data();
    const float uniform_contact2 = (p.radius + p.radius) * (p.radius + p.radius);
    std::vector<DiskPair>& out = chunk_contacts_[c];
    out.clear();
    for (const DiskPair q : chunk_pairs_[c]) {
        const auto [sep_x, sep_y] = separation<Periodic>(x[q.a], y[q.a], x[q.b], y[q.b], p);
        const float contact = UniformRadius ? 0.0f : radius[q.a] + radius[q.b];
        const float contact2 = UniformRadius ? uniform_contact2 : contact * contact;
        if (!(sep_x * sep_x + sep_y * sep_y >= contact2)) [[unlikely]] out.push_back(q);
    }
}

}  // namespace collide::cpu
