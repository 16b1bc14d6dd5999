// The parallel counting sort of the `cpu` backend's grid: for any thread count it produces the
// same cell order as a serial stable sort (every cell lists its disks in increasing index
// order), so the neighbour order of the contact pass does not depend on the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "cpu/cpu_cell_list.h"

namespace collide {
namespace {

struct Points {
    World world{0, 0, 100, 60, Boundary::reflect};
    std::vector<float> x, y;
};

// n points, uniformly random or already grouped by cell (as after the solver's reorder), a
// few of them outside the box or NaN (they go to border cells).
Points points(std::size_t n, bool grouped) {
    Points p;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<float> ux(-2.0f, 102.0f), uy(-2.0f, 62.0f);
    for (std::size_t i = 0; i < n; ++i) {
        p.x.push_back(ux(rng));
        p.y.push_back(uy(rng));
    }
    p.x[5] = std::nanf("");
    if (grouped) {
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return std::make_pair(std::floor(p.y[a]), std::floor(p.x[a])) < std::make_pair(std::floor(p.y[b]), std::floor(p.x[b]));
        });
        Points q = p;
        for (std::size_t k = 0; k < n; ++k) q.x[k] = p.x[order[k]], q.y[k] = p.y[order[k]];
        p = q;
    }
    return p;
}

std::vector<std::uint32_t> cell_order(const Points& p, int threads, std::vector<std::uint32_t>* starts = nullptr) {
    cpu::CellList grid;
    grid.configure(p.world, 1.0);
    grid.build_index(p.x.data(), p.y.data(), p.x.size(), threads);
    if (starts) starts->assign(grid.cell_start(), grid.cell_start() + grid.cell_count() + 1);
    return {grid.sorted_index(), grid.sorted_index() + p.x.size()};
}

TEST(CpuCellList, SameCellOrderForAnyThreadCountAsASerialStableSort) {
    for (bool grouped : {false, true}) {
        const Points p = points(20000, grouped);
        std::vector<std::uint32_t> starts;
        const auto one = cell_order(p, 1, &starts);
        // Serial reference: every slot range [starts[c], starts[c+1]) holds increasing indices
        // of disks in cell c, and the order is a permutation.
        std::vector<std::uint32_t> sorted = one;
        std::sort(sorted.begin(), sorted.end());
        for (std::uint32_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(sorted[k], k);
        for (std::size_t c = 0; c + 1 < starts.size(); ++c)
            for (std::uint32_t k = starts[c]; k + 1 < starts[c + 1]; ++k) ASSERT_LT(one[k], one[k + 1]);
        ASSERT_EQ(starts.back(), p.x.size());
        for (int threads : {2, 3, 8}) {
            std::vector<std::uint32_t> s;
            EXPECT_EQ(cell_order(p, threads, &s), one) << threads << " threads, grouped " << grouped;
            EXPECT_EQ(s, starts) << threads << " threads, grouped " << grouped;
        }
    }
}

}  // namespace
}  // namespace collide
