// HugePageAllocator (core/numerics/huge_page_allocator.h): large arrays start on a huge-page boundary,
// small ones are ordinary aligned allocations, and a vector using it behaves like any vector.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "core/numerics/huge_page_allocator.h"

namespace collide {
namespace {

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

struct alignas(64) Line {
    double values[8];
};

TEST(HugePageAllocator, LargeArraysStartOnAHugePage) {
    HugePageVector<Line> lines(3 * huge_page_bytes / sizeof(Line) + 1);
    EXPECT_EQ(address(lines.data()) % huge_page_bytes, 0u);
    HugePageVector<std::uint32_t> heads(huge_page_bytes / sizeof(std::uint32_t));  // exactly one page
    EXPECT_EQ(address(heads.data()) % huge_page_bytes, 0u);
}

TEST(HugePageAllocator, SmallArraysKeepTheirTypesAlignment) {
    HugePageVector<Line> lines(3);
    EXPECT_EQ(address(lines.data()) % alignof(Line), 0u);
    HugePageVector<double> values(5);
    EXPECT_EQ(address(values.data()) % alignof(double), 0u);
}

// Growing from small to large (and so from one kind of allocation to the other) and copying
// keep the values.
TEST(HugePageAllocator, VectorsKeepTheirValuesThroughGrowthAndCopies) {
    HugePageVector<std::uint64_t> v;
    const std::size_t n = huge_page_bytes / sizeof(std::uint64_t) * 2 + 7;
    for (std::uint64_t k = 0; k < n; ++k) v.push_back(k * k);
    for (std::uint64_t k = 0; k < n; k += 997) ASSERT_EQ(v[k], k * k);
    HugePageVector<std::uint64_t> copy = v;
    EXPECT_EQ(copy, v);
    copy.resize(10);
    copy.shrink_to_fit();
    EXPECT_EQ(copy[9], 81u);
    v.swap(copy);
    EXPECT_EQ(v.size(), 10u);
    EXPECT_EQ(copy.size(), n);
}

}  // namespace
}  // namespace collide
