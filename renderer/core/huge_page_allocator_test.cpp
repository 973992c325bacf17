#include "renderer/core/huge_page_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <new>
#include <numeric>
#include <vector>

namespace isotrace {
namespace {

TEST(HugePageAllocator, LargeBuffersStartOnAHugePageAndHoldTheirValues) {
    std::vector<std::uint64_t, HugePageAllocator<std::uint64_t>> large(3 * kHugePageBytes / sizeof(std::uint64_t) + 5);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % kHugePageBytes, 0u);
    for (std::uint64_t value : large) ASSERT_EQ(value, 0u);  // value-initialised like any vector
    std::iota(large.begin(), large.end(), std::uint64_t(0));
    EXPECT_EQ(large.back(), large.size() - 1);
    large.resize(large.size() * 2, 7);  // reallocates through the allocator again
    EXPECT_EQ(large[large.size() / 2 - 1], large.size() / 2 - 1);
    EXPECT_EQ(large.back(), 7u);
}

TEST(HugePageAllocator, SmallBuffersAreOrdinaryAllocations) {
    std::vector<int, HugePageAllocator<int>> small(100, 3);
    EXPECT_EQ(std::accumulate(small.begin(), small.end(), 0), 300);
}

TEST(HugePageAllocator, ImpossibleSizesThrow) {
    HugePageAllocator<std::uint64_t> allocator;
    EXPECT_THROW((void)allocator.allocate(std::size_t(-1) / 4), std::bad_array_new_length);
}

}  // namespace
}  // namespace isotrace
