// add_pair_shares and clear_pair_corrections (cpu/phase_kernels.h) over ranges of disks: each
// thread adds and clears the corrections of the disks it owns, so the sums must come out the
// same, bit for bit, however the disks are cut into ranges, and a range must leave the disks
// outside it untouched.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "cpu/phase_kernels.h"

namespace collide {
namespace {

constexpr std::uint32_t kDisks = 200;

struct ContactSet {
    std::vector<cpu::DiskPair> pairs;
    std::vector<cpu::PairShares> shares;
};

// 300 contacts among 200 disks (most disks in several), shares of mixed sign and magnitude so
// that the order of the additions shows in the last bits.
ContactSet random_contacts(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::uint32_t> disk(0, kDisks - 1);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    ContactSet set;
    for (int k = 0; k < 300; ++k) {
        std::uint32_t a = disk(rng), b = disk(rng);
        if (a == b) b = (a + 1) % kDisks;
        set.pairs.push_back({a, b});
        cpu::PairShares s{};
        for (int m = 0; m < 4; ++m) {
            s.a[m] = value(rng) * float(1 << (k % 12));
            s.b[m] = value(rng) / float(1 << (k % 7));
        }
        set.shares.push_back(s);
    }
    return set;
}

struct CorrectionArrays {
    std::vector<float> dx = std::vector<float>(kDisks), dy = dx, dvx = dx, dvy = dx;
    cpu::Corrections view() { return {dx.data(), dy.data(), dvx.data(), dvy.data()}; }
    bool operator==(const CorrectionArrays& o) const {
        auto same = [](const std::vector<float>& p, const std::vector<float>& q) {
            return std::memcmp(p.data(), q.data(), p.size() * sizeof(float)) == 0;
        };
        return same(dx, o.dx) && same(dy, o.dy) && same(dvx, o.dvx) && same(dvy, o.dvy);
    }
};

// The sums written out plainly: every disk's shares added in list order, a's before b's.
CorrectionArrays sums_in_list_order(const ContactSet& set) {
    CorrectionArrays out;
    for (std::size_t k = 0; k < set.pairs.size(); ++k) {
        const std::uint32_t a = set.pairs[k].a, b = set.pairs[k].b;
        out.dx[a] += set.shares[k].a[0], out.dy[a] += set.shares[k].a[1];
        out.dvx[a] += set.shares[k].a[2], out.dvy[a] += set.shares[k].a[3];
        out.dx[b] += set.shares[k].b[0], out.dy[b] += set.shares[k].b[1];
        out.dvx[b] += set.shares[k].b[2], out.dvy[b] += set.shares[k].b[3];
    }
    return out;
}

TEST(PairShares, SumsAreBitwiseTheSameWhateverRangesOwnTheDisks) {
    const ContactSet set = random_contacts(7);
    const CorrectionArrays expected = sums_in_list_order(set);
    for (const std::vector<std::uint32_t>& cuts :
         {std::vector<std::uint32_t>{0, kDisks}, {0, 1, kDisks}, {0, 63, 64, 150, kDisks}, {0, 50, 100, 150, 199, kDisks}}) {
        CorrectionArrays got;
        for (std::size_t r = 0; r + 1 < cuts.size(); ++r)  // ranges in reverse: the order of ranges is free
            cpu::add_pair_shares(set.pairs.data(), set.shares.data(), set.pairs.size(), got.view(),
                                 cuts[cuts.size() - 2 - r], cuts[cuts.size() - 1 - r]);
        EXPECT_TRUE(got == expected) << "cut into " << cuts.size() - 1 << " ranges";
    }
}

TEST(PairShares, ARangeAddsAndClearsOnlyItsOwnDisks) {
    const ContactSet set = random_contacts(11);
    const CorrectionArrays all = sums_in_list_order(set);
    CorrectionArrays got;
    cpu::add_pair_shares(set.pairs.data(), set.shares.data(), set.pairs.size(), got.view(), 40, 120);
    for (std::uint32_t i = 0; i < kDisks; ++i) {
        const bool inside = i >= 40 && i < 120;
        EXPECT_EQ(got.dvx[i], inside ? all.dvx[i] : 0.0f) << "disk " << i;
    }
    cpu::add_pair_shares(set.pairs.data(), set.shares.data(), set.pairs.size(), got.view(), 0, 40);
    cpu::add_pair_shares(set.pairs.data(), set.shares.data(), set.pairs.size(), got.view(), 120, kDisks);
    cpu::clear_pair_corrections(set.pairs.data(), set.pairs.size(), got.view(), 40, 120);
    for (std::uint32_t i = 0; i < kDisks; ++i) {
        const bool inside = i >= 40 && i < 120;
        EXPECT_EQ(got.dx[i], inside ? 0.0f : all.dx[i]) << "disk " << i;
        EXPECT_EQ(got.dvy[i], inside ? 0.0f : all.dvy[i]) << "disk " << i;
    }
    cpu::clear_pair_corrections(set.pairs.data(), set.pairs.size(), got.view(), 0, 40);
    cpu::clear_pair_corrections(set.pairs.data(), set.pairs.size(), got.view(), 120, kDisks);
    EXPECT_TRUE(got == CorrectionArrays{});
}

}  // namespace
}  // namespace collide
