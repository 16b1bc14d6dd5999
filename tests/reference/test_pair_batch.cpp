// PairBatch (reference/event/pair_batch.h) must give the collision times of
// event_time::pair_collision_time to the last bit, for the same neighbours, in the order
// they were gathered: the tuned solver's events, and so its pinned state hashes, rest on it.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "physics/collision_time.h"
#include "reference/event/pair_batch.h"

namespace collide {
namespace {

struct Pair {
    double dx, dy, ux, uy, sigma;
};

// Runs the pairs through a batch (flushing whenever it is full, as the solver does) and
// returns what it reported: (index of the pair, time).
std::vector<std::pair<std::uint32_t, double>> batch_hits(const std::vector<Pair>& pairs) {
    std::vector<std::pair<std::uint32_t, double>> hits;
    PairBatch batch;
    auto found = [&](std::uint32_t j, double dt) { hits.emplace_back(j, dt); };
    for (std::uint32_t j = 0; j < pairs.size(); ++j) {
        const Pair& q = pairs[j];
        batch.add(j, q.dx, q.dy, q.ux, q.uy, q.sigma);
        if (batch.full()) batch.flush(found);
    }
    batch.flush(found);
    return hits;
}

// What the one-at-a-time function says: every pair whose time is not "never", in order.
std::vector<std::pair<std::uint32_t, double>> scalar_hits(const std::vector<Pair>& pairs) {
    std::vector<std::pair<std::uint32_t, double>> hits;
    for (std::uint32_t j = 0; j < pairs.size(); ++j) {
        const Pair& q = pairs[j];
        const double dt = event_time::pair_collision_time(q.dx, q.dy, q.ux, q.uy, q.sigma);
        if (dt != event_time::never) hits.emplace_back(j, dt);
    }
    return hits;
}

// The same hits as the scalar function, in the same order, to the last bit (NaN included).
void expect_same_hits(const std::vector<Pair>& pairs) {
    const auto expected = scalar_hits(pairs);
    const auto hits = batch_hits(pairs);
    ASSERT_EQ(hits.size(), expected.size());
    for (std::size_t k = 0; k < hits.size(); ++k) {
        EXPECT_EQ(hits[k].first, expected[k].first) << "hit " << k;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(hits[k].second), std::bit_cast<std::uint64_t>(expected[k].second))
            << "pair " << hits[k].first << ": " << hits[k].second << " against " << expected[k].second;
    }
}

TEST(PairBatch, HandSolvedCasesGiveTheirTimesAndMissesAreLeftOut) {
    const std::vector<Pair> pairs = {
        {-4, 0, 2, 0, 1},          // head on: the gap of 3 closes at speed 2, t = 1.5
        {4, 0, 2, 0, 1},           // separating: never
        {-3, 1.0001, 1, 0, 1},     // misses by 1e-4: never
        {-1, 0, 1, 0, 1},          // touching and approaching: now
        {-1, 0, -1, 0, 1},         // touching and separating: never
        {-3, 0.5, 1, 0, 1},        // glancing: t = 3 - sqrt(3/4)
        {-4, 0, 0, 0, 1},          // at rest relative to each other: never
        {-1 + 1e-15, 0, 1, 0, 1},  // overlapping by round-off and approaching: now
    };
    const auto hits = batch_hits(pairs);
    ASSERT_EQ(hits.size(), 4u);
    EXPECT_EQ(hits[0].first, 0u);
    EXPECT_EQ(hits[0].second, 1.5);
    EXPECT_EQ(hits[1].first, 3u);
    EXPECT_EQ(hits[1].second, 0.0);
    EXPECT_EQ(hits[2].first, 5u);
    EXPECT_NEAR(hits[2].second, 3 - std::sqrt(0.75), 1e-15);
    EXPECT_EQ(hits[3].first, 7u);
    EXPECT_EQ(hits[3].second, 0.0);
}

// Many random pairs, more than one batch holds (so the batch is flushed part-way, as on a
// crowded prediction): the same hits, the same order, the same bits.
TEST(PairBatch, RandomPairsMatchThePairCollisionTimeBitForBit) {
    std::mt19937_64 rng(20261129);
    std::uniform_real_distribution<double> position(-3, 3), velocity(-2, 2), contact(0.5, 1.5);
    std::vector<Pair> pairs;
    for (int k = 0; k < 5 * PairBatch::capacity + 7; ++k)
        pairs.push_back({position(rng), position(rng), velocity(rng), velocity(rng), contact(rng)});
    // Some exactly touching pairs too (c = 0 exactly: |d| = sigma with a whole number).
    pairs.push_back({-1, 0, 0.5, 0.25, 1});
    pairs.push_back({0, 2, 0.1, -1, 2});
    ASSERT_GT(scalar_hits(pairs).size(), 20u);  // (the sample has hits of every kind to compare)
    expect_same_hits(pairs);
}

// The edges of the tests: a graze (D = 0 exactly: b = -3, c = 9, u.u = 1), an overlapping
// pair that separates, a NaN discriminant with c > 0 (an infinite velocity), a pair at rest
// relative to each other with c < 0: each as the scalar function decides it.
TEST(PairBatch, EdgesOfTheTestsTakeTheScalarFunctionsWay) {
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<Pair> pairs = {{-3, 1, 1, 0, 1}, {-0.5, 0, -1, 0, 1}, {4, 0, -inf, 0, 1}, {-0.5, 0, 0, 0, 1}};
    EXPECT_EQ(event_time::pair_collision_time(-3, 1, 1, 0, 1), event_time::never);  // (the graze is a miss)
    expect_same_hits(pairs);
}

// The same pair at the last place of one batch and the first of the next: both are reported,
// in that order, with the same time (so a caller taking the first of equal times takes the
// earlier one, as the solver's walk did before the batches).
TEST(PairBatch, AHitOnEachSideOfAFlushKeepsItsOrder) {
    std::vector<Pair> pairs(PairBatch::capacity + 1, Pair{4, 0, 2, 0, 1});  // separating: no hit
    pairs[PairBatch::capacity - 1] = pairs[PairBatch::capacity] = Pair{-4, 0, 2, 0, 1};  // t = 1.5
    const auto hits = batch_hits(pairs);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].first, std::uint32_t(PairBatch::capacity - 1));
    EXPECT_EQ(hits[1].first, std::uint32_t(PairBatch::capacity));
    EXPECT_EQ(hits[0].second, 1.5);
    EXPECT_EQ(hits[1].second, 1.5);
}

// A NaN takes the same way as in the scalar function: a miss where a test fails on it, a NaN
// time where it reaches the quotient (which the solver's "earlier than" never takes).
TEST(PairBatch, NotANumberTakesTheScalarFunctionsWay) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expect_same_hits({{nan, 0, 1, 0, 1}, {-4, 0, nan, 0, 1}, {-4, 0, 1, 0, nan}, {-4, 0, 1, nan, 1}});
}

TEST(PairBatch, AnEmptyBatchReportsNothing) {
    PairBatch batch;
    int calls = 0;
    batch.flush([&](std::uint32_t, double) { ++calls; });
    EXPECT_EQ(calls, 0);
    EXPECT_FALSE(batch.full());
}

}  // namespace
}  // namespace collide
