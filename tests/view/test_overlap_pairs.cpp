// The viewer's one pair search per frame: its marks must be exactly the overlapping pairs that
// brute force finds (midpoints and depths included), for any thread count, and the HUD's overlap
// figures taken from the marks must equal compute_metrics', which searches on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include "core/metrics.h"
#include "tests/support/test_scenes.h"
#include "view/overlap_pairs.h"

namespace collide::view {
namespace {

using MarkKey = std::tuple<double, double, double, double>;

double minimum_image(double d, double length) { return d - length * std::round(d / length); }

// Every pair i < j checked directly, as sorted (x, y, radius, depth) of the marks it implies.
std::vector<MarkKey> brute_force_marks(const Scene& scene, const ParticleState<double>& s) {
    std::vector<MarkKey> marks;
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            double dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
            if (scene.periodic()) dx = minimum_image(dx, scene.world.width()), dy = minimum_image(dy, scene.world.height());
            const double c = s.radius[i] + s.radius[j], d = std::hypot(dx, dy);
            if (d >= c) continue;
            double mx = s.x[i] + dx / 2, my = s.y[i] + dy / 2;
            if (scene.periodic()) {
                mx -= scene.world.width() * std::floor((mx - scene.world.xmin) / scene.world.width());
                my -= scene.world.height() * std::floor((my - scene.world.ymin) / scene.world.height());
            }
            marks.emplace_back(mx, my, std::min(s.radius[i], s.radius[j]), (c - d) / c);
        }
    std::sort(marks.begin(), marks.end());
    return marks;
}

std::vector<MarkKey> keys(const std::vector<OverlapMark>& marks) {
    std::vector<MarkKey> k;
    for (const OverlapMark& m : marks) k.emplace_back(m.x, m.y, m.radius, m.depth);
    std::sort(k.begin(), k.end());
    return k;
}

void expect_same_marks(const std::vector<MarkKey>& got, const std::vector<MarkKey>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_NEAR(std::get<0>(got[k]), std::get<0>(want[k]), 1e-9) << k;
        EXPECT_NEAR(std::get<1>(got[k]), std::get<1>(want[k]), 1e-9) << k;
        EXPECT_EQ(std::get<2>(got[k]), std::get<2>(want[k])) << k;
        EXPECT_NEAR(std::get<3>(got[k]), std::get<3>(want[k]), 1e-12) << k;
    }
}

// A crowded polydisperse state (overlaps allowed): enough disks for the search to use threads.
ParticleState<double> crowded_state(const Scene& scene, std::size_t n, unsigned seed) {
    auto s = test::random_gas(scene, n, 0.3, seed, /*allow_overlap=*/true);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> radius(0.03, 0.3);
    for (double& r : s.radius) r = radius(rng);
    return s;
}

class FinderVsBruteForce : public ::testing::TestWithParam<Boundary> {};

TEST_P(FinderVsBruteForce, SameMarksForOneAndTwoThreads) {
    const Scene scene = test::box_scene(40.0, 25.0, GetParam());
    const auto s = crowded_state(scene, 6000, 3);
    const auto want = brute_force_marks(scene, s);
    EXPECT_GT(want.size(), 500u);
    for (int threads : {1, 2}) {
        std::vector<OverlapMark> marks;
        OverlapFinder().find(scene.world, s, marks, threads);
        expect_same_marks(keys(marks), want);
    }
}

TEST_P(FinderVsBruteForce, SmallBoxesWithOneOrTwoCellsPerAxis) {
    for (double width : {1.0, 1.7, 2.5}) {
        const Scene scene = test::box_scene(width, width, GetParam());
        auto s = test::random_gas(scene, 30, 0.4, 7, /*allow_overlap=*/true);
        std::vector<OverlapMark> marks;
        OverlapFinder().find(scene.world, s, marks);
        expect_same_marks(keys(marks), brute_force_marks(scene, s));
    }
}

TEST_P(FinderVsBruteForce, HudFiguresFromTheMarksEqualComputeMetrics) {
    const Scene scene = test::box_scene(40.0, 25.0, GetParam());
    const auto s = crowded_state(scene, 6000, 5);
    std::vector<OverlapMark> marks;
    OverlapFinder().find(scene.world, s, marks, 2);
    const Metrics want = compute_metrics(scene, s, 1.5), got = frame_metrics(scene, s, 1.5, marks);
    EXPECT_GT(want.overlapping_pairs, 0);
    EXPECT_GT(want.max_overlap_beyond_step, 0);
    EXPECT_EQ(got.overlapping_pairs, want.overlapping_pairs);
    EXPECT_DOUBLE_EQ(got.max_overlap, want.max_overlap);
    EXPECT_NEAR(got.mean_overlap, want.mean_overlap, 1e-14);
    EXPECT_DOUBLE_EQ(got.max_overlap_beyond_step, want.max_overlap_beyond_step);
    EXPECT_EQ(got.kinetic_energy, want.kinetic_energy);
    EXPECT_EQ(got.momentum_x, want.momentum_x);
    EXPECT_EQ(got.time, want.time);
}

INSTANTIATE_TEST_SUITE_P(Boundaries, FinderVsBruteForce, ::testing::Values(Boundary::reflect, Boundary::periodic),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(OverlapFinder, FindsAPairAcrossAPeriodicWallAtItsMinimumImageMidpoint) {
    const Scene scene = test::box_scene(10, 10, Boundary::periodic);
    const auto state = test::make_state({{0.2, 5.0, 0, 0, 0.5, 1}, {9.9, 5.0, 0, 0, 0.5, 1}, {5, 5, 0, 0, 0.5, 1}});
    std::vector<OverlapMark> marks;
    OverlapFinder().find(scene.world, state, marks);
    ASSERT_EQ(marks.size(), 1u);
    EXPECT_NEAR(marks[0].x, 0.05, 1e-12);
    EXPECT_NEAR(marks[0].depth, 0.7, 1e-12);
}

TEST(OverlapFinder, ADiskWithANonFiniteVelocityIsLeftOutAsInTheMetrics) {
    const Scene scene = test::box_scene(10, 10);
    auto state = test::make_state({{5.0, 5.0, 0, 0, 0.5, 1}, {5.5, 5.0, 0, 0, 0.5, 1}});
    std::vector<OverlapMark> marks;
    OverlapFinder().find(scene.world, state, marks);
    EXPECT_EQ(marks.size(), 1u);
    state.vx[1] = std::nan("");
    OverlapFinder().find(scene.world, state, marks);
    EXPECT_TRUE(marks.empty());
}

}  // namespace
}  // namespace collide::view
