// The event solver's cell list (reference/event/event_cell_list.h): the blocks of cells its prefetching
// requests must hold the lists the solver then reads.
#include "reference/event/event_cell_list.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>
#include <vector>

namespace collide {
namespace {

struct Record {
    CellLinks links;
};

bool holds(const CellList::Block& b, std::int64_t x, std::int64_t y) {
    return b.x0 <= x && x <= b.x1 && b.y0 <= y && y <= b.y1;
}

// A 10 x 10 grid of unit cells with one disk in each: disk k sits in column k % 10, row k / 10.
struct FullGrid {
    CellList cells;
    std::vector<Record> disks;
    explicit FullGrid(Boundary boundary) : disks(100) {
        cells.configure(World{0, 0, 10, 10, boundary}, 1.0, disks.size());
        for (std::uint32_t k = 0; k < disks.size(); ++k) cells.insert(disks, k, k % 10, k / 10);
    }
};

// Before a crossing, crossing_block names the cell the disk enters and the three cells that
// for_each_entered walks once it is there, in a block of six cells (the other two are read
// when the crossing has to predict afresh).
TEST(EventCellList, CrossingBlockHoldsTheCellEnteredAndTheCellsWalkedAfter) {
    const std::pair<std::int64_t, std::int64_t> step[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    for (std::uint32_t border = 0; border < 4; ++border) {
        SCOPED_TRACE("border " + std::to_string(border));
        FullGrid g(Boundary::reflect);
        const std::uint32_t i = 5 * 10 + 5;  // column 5, row 5
        const CellList::Block b = g.cells.crossing_block(g.disks[i].links, border);
        EXPECT_EQ((b.x1 - b.x0 + 1) * (b.y1 - b.y0 + 1), 6);
        const std::int64_t cx = 5 + step[border].first, cy = 5 + step[border].second;
        EXPECT_TRUE(holds(b, cx, cy)) << "the cell entered";
        g.cells.remove(g.disks, i);
        g.cells.insert(g.disks, i, cx, cy);
        std::set<std::uint32_t> walked;
        g.cells.for_each_entered(g.disks, i, border, [&](std::uint32_t j) { walked.insert(j); });
        EXPECT_EQ(walked.size(), 3u);
        for (std::uint32_t j : walked)
            EXPECT_TRUE(holds(b, g.cells.column(g.disks[j].links), g.cells.row(g.disks[j].links))) << "disk " << j;
    }
}

// Blocks that would wrap around a periodic side or reach past a wall are not prefetched: empty.
TEST(EventCellList, BlocksAtTheEdgeAreEmpty) {
    const auto empty = [](const CellList::Block& b) { return b.x1 < b.x0 || b.y1 < b.y0; };
    for (Boundary boundary : {Boundary::periodic, Boundary::reflect}) {
        FullGrid g(boundary);
        const auto at = [&](int column, int row) -> const CellLinks& { return g.disks[std::size_t(row * 10 + column)].links; };
        for (const auto& [column, row] : {std::pair{0, 0}, std::pair{9, 9}, std::pair{0, 5}, std::pair{5, 9}})
            EXPECT_TRUE(empty(g.cells.neighbourhood_block(at(column, row)))) << column << ", " << row;
        EXPECT_FALSE(empty(g.cells.neighbourhood_block(at(1, 1))));
        EXPECT_FALSE(empty(g.cells.neighbourhood_block(at(8, 8))));
        // From column 1 towards column 0 the cells beyond would be column -1; from 8 towards 9, column 10.
        EXPECT_TRUE(empty(g.cells.crossing_block(at(1, 5), 0)));
        EXPECT_FALSE(empty(g.cells.crossing_block(at(1, 5), 1)));
        EXPECT_TRUE(empty(g.cells.crossing_block(at(8, 5), 1)));
        EXPECT_FALSE(empty(g.cells.crossing_block(at(8, 5), 0)));
        EXPECT_TRUE(empty(g.cells.crossing_block(at(5, 8), 3)));
        EXPECT_TRUE(empty(g.cells.crossing_block(at(5, 1), 2)));
        EXPECT_FALSE(empty(g.cells.crossing_block(at(5, 2), 2)));
        EXPECT_FALSE(empty(g.cells.crossing_block(at(5, 7), 3)));
    }
}

}  // namespace
}  // namespace collide
