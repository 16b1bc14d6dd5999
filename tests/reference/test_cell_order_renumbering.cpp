// The tuned event solver's renumbering in cell order (reference/event/cell_order_renumbering.h):
// a permutation of the disks that must carry every disk's state, prediction and calendar entry
// along, so that the solver's events are the same, bit for bit, as without it.
#include "reference/event/cell_order_renumbering.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace collide {
namespace {

constexpr double never = std::numeric_limits<double>::infinity();

// 300 disks scattered over a 10 x 10 grid of unit cells, each with a prediction naming another
// disk, a calendar time (some shared, some never) and a value in a per-disk array; numbered in
// the order they were made, which is not cell order.
struct Scatter {
    static constexpr std::uint32_t n = 300;
    CellList cells;
    EventArray<EventDisk> disks;
    EventQueue<EventSlot> queue;
    std::vector<double> values;
    std::vector<std::uint32_t> original;

    Scatter() : disks(n), values(n), original(n) {
        std::mt19937 random(7);
        std::uniform_real_distribution<double> coordinate(0.0, 10.0), time(0.0, 5.0);
        cells.configure(World{0, 0, 10, 10, Boundary::periodic}, 1.0, n);
        queue.reset(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            EventDisk& d = disks[i];
            d = EventDisk{coordinate(random), coordinate(random), 0.1 * i, -0.2 * i, 0.01 * i, 0.1, i % 7, CellLinks{}};
            cells.insert(disks, i, cells.column_of(d.x), cells.row_of(d.y));
            EventPrediction& p = queue.payload(i).prediction;
            p.partner = (i * 37 + 11) % n;
            p.partner_count = i;
            p.pair_time = time(random);
            p.kind = EventKind::pair;
            queue.payload(i).inv_mass = 1.0 / (1 + i);
            // Every tenth disk shares its time with the next one (ties), every 13th has none.
            const double t = i % 13 == 0 ? never : i % 10 == 1 ? queue.time_of(i - 1) : p.pair_time;
            queue.update(i, t);
            values[i] = 1.5 * i;
            original[i] = i;
        }
    }
    // The disks of each cell, in the order the list walks them, as original numbers.
    std::vector<std::vector<std::uint32_t>> cell_contents() const {
        std::vector<std::vector<std::uint32_t>> contents(100);
        std::vector<std::uint32_t> order;
        cells.cell_order(disks, order);
        for (std::uint32_t j : order) contents[disks[j].links.cell].push_back(original[j]);
        return contents;
    }
    // The calendar's order of service, as original numbers (served from a copy).
    std::vector<std::uint32_t> service_order() const {
        EventQueue<EventSlot> q = queue;
        std::vector<std::uint32_t> served;
        while (served.size() < n && q.top_time() < never) {
            const std::uint32_t p = q.top();
            served.push_back(original[p]);
            q.update(p, never);
        }
        return served;
    }
    void renumber(CellOrderRenumbering& r) { r.apply(disks, cells, queue, {&values}, original); }
};

TEST(CellOrderRenumbering, IsAPermutationIntoCellOrder) {
    Scatter s;
    CellOrderRenumbering r;
    s.renumber(r);
    std::vector<std::uint32_t> sorted = r.order();
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t k = 0; k < Scatter::n; ++k) {
        ASSERT_EQ(sorted[k], k) << "order is not a permutation";
        EXPECT_EQ(r.new_of()[r.order()[k]], k) << "new_of is not the inverse of order";
        EXPECT_EQ(s.original[k], r.order()[k]);
        if (k > 0) {
            EXPECT_LE(s.disks[k - 1].links.cell, s.disks[k].links.cell) << "not in cell order at " << k;
        }
    }
    EXPECT_NE(r.order(), sorted) << "the scatter was already in cell order: the test tests nothing";
}

TEST(CellOrderRenumbering, CarriesEveryDisksStatePredictionAndCellAlong) {
    Scatter before, s;
    const auto contents_before = before.cell_contents();
    CellOrderRenumbering r;
    s.renumber(r);
    for (std::uint32_t k = 0; k < Scatter::n; ++k) {
        const std::uint32_t was = s.original[k];
        const EventDisk &now = s.disks[k], &then = before.disks[was];
        EXPECT_EQ(now.x, then.x);
        EXPECT_EQ(now.vy, then.vy);
        EXPECT_EQ(now.t, then.t);
        EXPECT_EQ(now.count, then.count);
        EXPECT_EQ(now.links.cell, then.links.cell);
        EXPECT_EQ(s.values[k], before.values[was]);
        EXPECT_EQ(s.queue.time_of(k), before.queue.time_of(was));
        EXPECT_EQ(s.queue.payload(k).inv_mass, before.queue.payload(was).inv_mass);
        const EventPrediction &p = s.queue.payload(k).prediction, &q = before.queue.payload(was).prediction;
        EXPECT_EQ(s.original[p.partner], q.partner) << "the partner was not renamed";
        EXPECT_EQ(p.pair_time, q.pair_time);
        EXPECT_EQ(p.partner_count, q.partner_count);
    }
    EXPECT_EQ(s.cell_contents(), contents_before) << "a cell's list changed its disks or their order";
}

// The calendar serves the same disks in the same order, ties included, whether the
// renumbering comes before the calendar is first built or after.
TEST(CellOrderRenumbering, CalendarServesTheSameEventsInTheSameOrder) {
    for (bool built : {false, true}) {
        SCOPED_TRACE(built ? "calendar built" : "calendar not yet built");
        Scatter s;
        if (built) s.queue.top();
        const std::vector<std::uint32_t> expected = s.service_order();
        ASSERT_GT(expected.size(), 250u);
        CellOrderRenumbering r;
        s.renumber(r);
        EXPECT_EQ(s.service_order(), expected);
        s.renumber(r);  // (twice: already in cell order, it must change nothing)
        EXPECT_EQ(s.service_order(), expected);
    }
}

TEST(CellOrderRenumbering, IsDueEveryIntervalEvents) {
    Scatter s;
    CellOrderRenumbering r;
    r.set_interval(3);
    s.renumber(r);  // (restarts the count)
    EXPECT_FALSE(r.count_event());
    EXPECT_FALSE(r.count_event());
    EXPECT_TRUE(r.count_event());
    s.renumber(r);
    EXPECT_FALSE(r.count_event());
    EXPECT_EQ(CellOrderRenumbering::default_interval(1000), renumber_events_per_disk * 1000 + 1000);
}

}  // namespace
}  // namespace collide
