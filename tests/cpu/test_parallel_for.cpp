// parallel_for and parallel_test_then_work (cpu/parallel_for.h): every item visited once, in
// chunks that cover the range; the work after a test runs only when the test's total is zero,
// and the total returned is the test's; the same on the pool and inline.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <vector>

#include "cpu/parallel_for.h"

namespace collide {
namespace {

// Counts, per item, how often a loop body visited it.
struct Visits {
    explicit Visits(std::size_t n) : count(n) {}
    std::vector<std::atomic<int>> count;
    bool each_once() const {
        for (const auto& c : count)
            if (c.load() != 1) return false;
        return true;
    }
    bool none() const {
        for (const auto& c : count)
            if (c.load() != 0) return false;
        return true;
    }
};

TEST(ParallelFor, VisitsEveryItemOnceAndSumsTheCounts) {
    for (const int threads : {1, 2, 3})
        for (const std::size_t n : {std::size_t(0), std::size_t(5), std::size_t(10000), std::size_t(12345)}) {
            Visits visits(n);
            const std::int64_t total = cpu::parallel_for(n, threads, [&](std::size_t b, std::size_t e) {
                for (std::size_t i = b; i < e; ++i) ++visits.count[i];
                return std::int64_t(e - b);
            });
            EXPECT_TRUE(visits.each_once()) << threads << " threads, n = " << n;
            EXPECT_EQ(total, std::int64_t(n));
        }
}

// A test that fails on the items in `failing` (counting them) over n disks, then work over m
// chunks; returns what parallel_test_then_work returned.
std::int64_t test_then_work(std::size_t n, const std::vector<std::size_t>& failing, Visits& tested, Visits& worked,
                            int threads) {
    return cpu::parallel_test_then_work(
        n, [&](std::size_t b, std::size_t e) {
            std::int64_t failed = 0;
            for (std::size_t i = b; i < e; ++i) {
                ++tested.count[i];
                for (const std::size_t f : failing) failed += f == i;
            }
            return failed;
        },
        worked.count.size(), 1, [&](std::size_t b, std::size_t e) {
            for (std::size_t c = b; c < e; ++c) ++worked.count[c];
            return std::int64_t(0);
        }, threads, n);
}

TEST(ParallelTestThenWork, WorksOnlyWhenTheTestPassesOnThePoolAndInline) {
    for (const int threads : {1, 2, 4})
        for (const std::size_t n : {std::size_t(100), std::size_t(20000)}) {  // inline, then on the pool
            Visits tested(n), worked(8);
            EXPECT_EQ(test_then_work(n, {}, tested, worked, threads), 0);
            EXPECT_TRUE(tested.each_once()) << threads << " threads, n = " << n;
            EXPECT_TRUE(worked.each_once()) << "the test passed: every chunk of work once";

            Visits tested_again(n), not_worked(8);
            EXPECT_EQ(test_then_work(n, {3, n - 1}, tested_again, not_worked, threads), 2) << "the test's total";
            EXPECT_TRUE(tested_again.each_once());
            EXPECT_TRUE(not_worked.none()) << threads << " threads, n = " << n << ": the test failed, no work";
        }
}

}  // namespace
}  // namespace collide
