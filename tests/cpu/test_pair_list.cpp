// PairList (cpu/pair_list.h): as long as it is not stale, the contacts it finds are exactly the
// pairs a search over all pairs finds; it says stale once a disk has moved its limit, or has
// a NaN position.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "cpu/pair_list.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using Contacts = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

struct ListCase {
    Scene scene;
    ParticleState<float> state;
    cpu::PhaseParams params;
};

// 600 disks of radii 0.4 and 0.5 in a 40 x 40 box: area fraction about 0.3.
ListCase list_case(Boundary boundary, std::uint64_t seed) {
    ListCase c;
    c.scene = test::box_scene(40, 40, boundary);
    ParticleState<double> gas = test::random_gas(c.scene, 600, 0.5, seed);
    for (std::size_t i = 0; i < gas.size(); i += 3) gas.radius[i] = 0.4;
    c.state = gas.as<float>();
    const World& w = c.scene.world;
    c.params.xmin = float(w.xmin);
    c.params.ymin = float(w.ymin);
    c.params.xmax = float(w.xmax);
    c.params.ymax = float(w.ymax);
    c.params.width = float(w.width());
    c.params.height = float(w.height());
    return c;
}

// Every pair closer than r_a + r_b, by the contact test of the cpu backend over all pairs.
Contacts all_pairs_in_contact(const ListCase& c) {
    Contacts found;
    const auto& s = c.state;
    const bool periodic = c.scene.world.boundary == Boundary::periodic;
    for (std::uint32_t a = 0; a < s.size(); ++a)
        for (std::uint32_t b = a + 1; b < s.size(); ++b) {
            float dx = s.x[a] - s.x[b], dy = s.y[a] - s.y[b];
            if (periodic) {
                dx = WallLaw<float>::minimum_image(dx, c.params.width);
                dy = WallLaw<float>::minimum_image(dy, c.params.height);
            }
            const float contact = s.radius[a] + s.radius[b];
            if (!(dx * dx + dy * dy >= contact * contact)) found.emplace_back(a, b);
        }
    return found;
}

template <bool Periodic>
Contacts list_contacts(cpu::PairList& list, const ListCase& c) {
    list.find_contacts<false, Periodic>(c.state, c.params, 1);
    Contacts found;
    for (const cpu::DiskPair& q : list.contacts()) found.emplace_back(std::min(q.a, q.b), std::max(q.a, q.b));
    std::sort(found.begin(), found.end());
    return found;
}

// The same through search_unless_stale(): the contacts, or nothing when it says stale. (600
// disks run inline whatever the thread count; the one-region path itself is tested in
// test_parallel_for.cpp.)
template <bool Periodic>
std::optional<Contacts> contacts_unless_stale(cpu::PairList& list, const ListCase& c) {
    std::size_t chunks_seen = 0;
    if (!list.search_unless_stale<false, Periodic>(c.state, c.params, 2,
                                                   [&](std::size_t, const std::vector<cpu::DiskPair>&) { ++chunks_seen; }))
        return std::nullopt;
    EXPECT_EQ(chunks_seen, list.chunks()) << "every chunk searched once";
    Contacts found;
    for (const cpu::DiskPair& q : list.contacts()) found.emplace_back(std::min(q.a, q.b), std::max(q.a, q.b));
    std::sort(found.begin(), found.end());
    return found;
}

// Moves every disk by `step` in a random direction, keeping each within `limit` of where it
// was at the build (x0, y0), so that the list must still hold.
void jiggle(ListCase& c, const std::vector<float>& x0, const std::vector<float>& y0, float step, float limit,
            std::mt19937_64& rng) {
    std::uniform_real_distribution<float> angle(0.0f, 6.2831853f);
    for (std::size_t i = 0; i < c.state.size(); ++i) {
        const float a = angle(rng);
        const float x = c.state.x[i] + step * std::cos(a), y = c.state.y[i] + step * std::sin(a);
        if (std::hypot(x - x0[i], y - y0[i]) < limit) {
            c.state.x[i] = x;
            c.state.y[i] = y;
        }
    }
}

template <bool Periodic>
void check_list_until_stale(Boundary boundary, bool in_cell_order) {
    ListCase c = list_case(boundary, 3);
    const float skin = 0.5f, r_max = 0.5f;
    cpu::CellList grid;
    grid.configure(c.scene.world, 2.0 * r_max + skin);
    grid.build_index(c.state.x.data(), c.state.y.data(), c.state.size(), 1);
    if (in_cell_order) {  // move the disks into the grid's cell order, as CpuSolver's reorder does
        ParticleState<float> sorted = c.state;
        for (std::size_t k = 0; k < c.state.size(); ++k) {
            const std::uint32_t i = grid.sorted_index()[k];
            sorted.x[k] = c.state.x[i];
            sorted.y[k] = c.state.y[i];
            sorted.radius[k] = c.state.radius[i];
        }
        c.state = sorted;
        grid.build_index(c.state.x.data(), c.state.y.data(), c.state.size(), 1);
    }
    cpu::PairList list;
    list.reset(skin);
    EXPECT_TRUE((list.is_stale<Periodic>(c.state, c.params, 1))) << "no list yet";
    if (in_cell_order)
        list.build<false, Periodic, true>(c.state, grid, c.params, 2);
    else
        list.build<false, Periodic, false>(c.state, grid, c.params, 2);
    ASSERT_FALSE((list.is_stale<Periodic>(c.state, c.params, 1)));
    const std::vector<float> x0 = c.state.x, y0 = c.state.y;
    // Squeeze the gas a little towards contact first: a list that only ever saw no contacts
    // would prove nothing. Then wander, each disk within the move limit of its build position.
    std::mt19937_64 rng(11);
    const float limit = cpu::PairList::kMoveFraction * skin * 0.999f;
    std::size_t contacts_seen = 0;
    for (int round = 0; round < 40; ++round) {
        jiggle(c, x0, y0, 0.05f, limit, rng);
        ASSERT_FALSE((list.is_stale<Periodic>(c.state, c.params, 2))) << "round " << round;
        const Contacts expected = all_pairs_in_contact(c);
        ASSERT_EQ(list_contacts<Periodic>(list, c), expected) << "round " << round;
        ASSERT_EQ(contacts_unless_stale<Periodic>(list, c), expected) << "round " << round;
        contacts_seen += expected.size();
    }
    EXPECT_GT(contacts_seen, 40u) << "the rounds should have brought disks into contact";
    // One disk one step past its limit: stale.
    c.state.x[7] = x0[7] + cpu::PairList::kMoveFraction * skin * 1.001f;
    c.state.y[7] = y0[7];
    EXPECT_TRUE((list.is_stale<Periodic>(c.state, c.params, 1)));
    EXPECT_EQ(contacts_unless_stale<Periodic>(list, c), std::nullopt) << "stale: nothing searched";
}

TEST(PairList, FindsExactlyTheContactsOfAllPairsUntilStale) {
    check_list_until_stale<false>(Boundary::reflect, true);
    check_list_until_stale<false>(Boundary::reflect, false);
}

TEST(PairList, FindsExactlyTheContactsOfAllPairsUntilStaleAcrossPeriodicWalls) {
    check_list_until_stale<true>(Boundary::periodic, true);
    check_list_until_stale<true>(Boundary::periodic, false);
}

TEST(PairList, HoldsEachPairOnceWhateverTheThreadCount) {
    ListCase c = list_case(Boundary::reflect, 5);
    cpu::CellList grid;
    grid.configure(c.scene.world, 1.5);
    grid.build_index(c.state.x.data(), c.state.y.data(), c.state.size(), 1);
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> lists;
    for (int threads : {1, 2, 8}) {
        cpu::PairList list;
        list.reset(0.5f);
        list.build<false, false, false>(c.state, grid, c.params, threads);
        // The list itself, read as the contacts of the same state with every disk grown by
        // half the skin: contact at r_a + r_b + skin is exactly the list's reach.
        ListCase grown = c;
        for (float& r : grown.state.radius) r += 0.25f;
        list.find_contacts<false, false>(grown.state, grown.params, threads);
        std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
        for (const cpu::DiskPair& q : list.contacts()) {
            ASSERT_LT(q.a, q.b);
            pairs.emplace_back(q.a, q.b);
        }
        lists.push_back(pairs);
    }
    EXPECT_EQ(lists[1], lists[0]) << "2 threads: the same pairs in the same order";
    EXPECT_EQ(lists[2], lists[0]) << "8 threads";
    auto sorted = lists[0];
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a pair listed twice";
    EXPECT_GT(sorted.size(), 300u);
}

TEST(PairList, NanPositionMakesTheListStale) {
    ListCase c = list_case(Boundary::reflect, 9);
    cpu::CellList grid;
    grid.configure(c.scene.world, 1.5);
    grid.build_index(c.state.x.data(), c.state.y.data(), c.state.size(), 1);
    cpu::PairList list;
    list.reset(0.5f);
    list.build<false, false, false>(c.state, grid, c.params, 1);
    ASSERT_FALSE((list.is_stale<false>(c.state, c.params, 1)));
    c.state.y[42] = std::nanf("");
    EXPECT_TRUE((list.is_stale<false>(c.state, c.params, 1)));
}

}  // namespace
}  // namespace collide
