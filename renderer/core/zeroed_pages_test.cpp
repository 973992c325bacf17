#include "renderer/core/zeroed_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <new>
#include <numeric>
#include <utility>

namespace isotrace {
namespace {

struct Sums {
    double value = 0;
    std::uint32_t count = 0;
};

TEST(ZeroedPages, LargeBuffersStartZeroedOnAHugePageAndHoldTheirValues) {
    // Several times over, so that later buffers can land where earlier ones were freed.
    for (int round = 0; round < 3; ++round) {
        ZeroedPages<std::uint64_t> large(3 * kHugePageBytes / sizeof(std::uint64_t) + 5);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % kHugePageBytes, 0u);
        for (std::uint64_t value : large) ASSERT_EQ(value, 0u);
        std::iota(large.begin(), large.end(), std::uint64_t(1));
        EXPECT_EQ(large[large.size() - 1], large.size());
    }
}

TEST(ZeroedPages, SmallBuffersStartZeroedToo) {
    for (int round = 0; round < 3; ++round) {
        ZeroedPages<Sums> small(100);
        for (const Sums& s : small) {
            ASSERT_EQ(s.value, 0.0);
            ASSERT_EQ(s.count, 0u);
        }
        for (Sums& s : small) s = {1.5, 3};
    }
}

TEST(ZeroedPages, MovesHandOverTheBuffer) {
    ZeroedPages<std::uint64_t> a(kHugePageBytes / sizeof(std::uint64_t) * 2);
    a[7] = 42;
    const std::uint64_t* first = a.data();
    ZeroedPages<std::uint64_t> b(std::move(a));
    EXPECT_EQ(b.data(), first);
    EXPECT_EQ(b[7], 42u);
    EXPECT_TRUE(a.empty());  // NOLINT(bugprone-use-after-move): a moved-from buffer is empty
    ZeroedPages<std::uint64_t> c(10);
    c = std::move(b);
    EXPECT_EQ(c[7], 42u);
    EXPECT_EQ(c.size(), kHugePageBytes / sizeof(std::uint64_t) * 2);
}

TEST(ZeroedPages, ImpossibleSizesThrow) {
    EXPECT_THROW(ZeroedPages<std::uint64_t>(std::size_t(-1) / 4), std::bad_array_new_length);
}

}  // namespace
}  // namespace isotrace
