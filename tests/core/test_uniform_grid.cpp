// The grid's candidate pairs must contain every overlapping pair that brute force finds.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>

#include "physics/stepping_laws.h"
#include "core/uniform_grid.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

bool touching(const Scene& scene, const ParticleState<double>& s, std::size_t i, std::size_t j) {
    double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j];
    if (scene.periodic()) {
        dx = WallLaw<double>::minimum_image(dx, scene.world.width());
        dy = WallLaw<double>::minimum_image(dy, scene.world.height());
    }
    const double c = s.radius[i] + s.radius[j];
    return dx * dx + dy * dy < c * c;
}

PairSet brute_force_pairs(const Scene& scene, const ParticleState<double>& s) {
    PairSet pairs;
    for (std::uint32_t i = 0; i < s.size(); ++i)
        for (std::uint32_t j = i + 1; j < s.size(); ++j)
            if (touching(scene, s, i, j)) pairs.insert({i, j});
    return pairs;
}

PairSet grid_pairs(const Scene& scene, const ParticleState<double>& s, double r_max) {
    UniformGrid<double> grid;
    grid.configure(scene.world, 2 * r_max);
    grid.build(s.x.data(), s.y.data(), s.size());
    PairSet pairs;
    std::multiset<std::pair<std::uint32_t, std::uint32_t>> visits;
    for (std::uint32_t i = 0; i < s.size(); ++i)
        grid.for_each_candidate(s.x[i], s.y[i], [&](std::uint32_t j) {
            if (j > i && touching(scene, s, i, j)) { pairs.insert({i, j}); visits.insert({i, j}); }
        });
    EXPECT_EQ(visits.size(), pairs.size()) << "a pair was visited twice";
    return pairs;
}

// Random polydisperse states with overlaps allowed, so that there are many contacts.
ParticleState<double> random_overlapping_state(const Scene& scene, std::size_t n, double r_max, unsigned seed) {
    auto s = test::random_gas(scene, n, r_max, seed, /*allow_overlap=*/true);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ur(0.1 * r_max, r_max);
    for (auto& r : s.radius) r = ur(rng);
    return s;
}

class GridVsBruteForce : public ::testing::TestWithParam<Boundary> {};

TEST_P(GridVsBruteForce, SamePairsOnRandomStates) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const Scene scene = test::box_scene(10.0, 7.0, GetParam());
        const auto s = random_overlapping_state(scene, 400, 0.3, seed);
        const auto expected = brute_force_pairs(scene, s);
        EXPECT_GT(expected.size(), 50u);
        EXPECT_EQ(grid_pairs(scene, s, 0.3), expected) << "seed " << seed;
    }
}

TEST_P(GridVsBruteForce, SmallBoxWithFewCells) {
    // 1 and 2 cells per axis: the periodic neighbourhood must not visit a cell twice.
    for (double width : {1.0, 1.7, 2.5}) {
        const Scene scene = test::box_scene(width, width, GetParam());
        const auto s = random_overlapping_state(scene, 30, 0.4, 7);
        EXPECT_EQ(grid_pairs(scene, s, 0.4), brute_force_pairs(scene, s)) << "width " << width;
    }
}

TEST_P(GridVsBruteForce, NeighbourRangesHoldExactlyTheCandidates) {
    // Every cell, also in boxes of 1 and 2 cells per axis: the slot ranges must name the same
    // disks as for_each_candidate, each once.
    for (double width : {1.0, 1.7, 2.5, 10.0}) {
        const Scene scene = test::box_scene(width, 7.0, GetParam());
        const auto s = random_overlapping_state(scene, 200, 0.4, 11);
        UniformGrid<double> grid;
        grid.configure(scene.world, 0.8);
        grid.build(s.x.data(), s.y.data(), s.size());
        for (std::int64_t cy = 0; cy < grid.cells_y(); ++cy)
            for (std::int64_t cx = 0; cx < grid.cells_x(); ++cx) {
                const double px = scene.world.xmin + (double(cx) + 0.5) * scene.world.width() / double(grid.cells_x());
                const double py = scene.world.ymin + (double(cy) + 0.5) * scene.world.height() / double(grid.cells_y());
                std::multiset<std::uint32_t> from_candidates, from_ranges;
                grid.for_each_candidate(px, py, [&](std::uint32_t j) { from_candidates.insert(j); });
                grid.for_each_neighbour_range(cx, cy, [&](std::uint32_t begin, std::uint32_t end) {
                    for (std::uint32_t k = begin; k < end; ++k) from_ranges.insert(grid.sorted_index()[k]);
                });
                EXPECT_EQ(from_ranges, from_candidates) << "width " << width << " cell " << cx << "," << cy;
            }
    }
}

INSTANTIATE_TEST_SUITE_P(Boundaries, GridVsBruteForce,
                         ::testing::Values(Boundary::reflect, Boundary::periodic),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(UniformGrid, CountingSortKeepsIndexOrderWithinCells) {
    const Scene scene = test::box_scene(4.0, 4.0);
    auto s = test::make_state({{0.5, 0.5, 0, 0, 0.1, 1}, {3.5, 3.5, 0, 0, 0.1, 1}, {0.6, 0.4, 0, 0, 0.1, 1}});
    UniformGrid<double> grid;
    grid.configure(scene.world, 1.0);
    grid.build(s.x.data(), s.y.data(), s.size());
    EXPECT_EQ(grid.cells_x(), 4);
    const auto& start = grid.cell_start();
    EXPECT_EQ(start[1] - start[0], 2u);
    EXPECT_EQ(grid.sorted_index()[start[0]], 0u);
    EXPECT_EQ(grid.sorted_index()[start[0] + 1], 2u);
    EXPECT_EQ(start.back(), 3u);
}

TEST(UniformGrid, PointsOutsideTheBoxAndNaNLandInBorderCells) {
    const Scene scene = test::box_scene(4.0, 4.0);
    UniformGrid<double> grid;
    grid.configure(scene.world, 1.0);
    EXPECT_EQ(grid.cell_x(-0.5), 0);
    EXPECT_EQ(grid.cell_x(4.5), 3);
    EXPECT_EQ(grid.cell_x(std::nan("")), 0);
}

}  // namespace
}  // namespace collide
