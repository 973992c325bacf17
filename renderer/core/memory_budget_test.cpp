#include "renderer/core/memory_budget.h"

#include <gtest/gtest.h>

#include <limits>

namespace isotrace {
namespace {

TEST(MemoryBudget, ChargesUpToTheLimitAndRefusesBeyondWithTheFigures) {
    MemoryBudget budget(1'000'000);
    budget.charge(600'000, "film");
    EXPECT_EQ(budget.charged_bytes(), 600'000u);
    try {
        budget.charge(500'000, "texture sky.exr", {"scene.json", 4, 9}, "lights[0].file");
        FAIL() << "expected the budget to refuse";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_EQ(error.location().line, 4);
        EXPECT_EQ(error.field(), "lights[0].file");
        EXPECT_NE(message.find("texture sky.exr needs about 500 kB"), std::string::npos) << message;
        EXPECT_NE(message.find("600 kB already"), std::string::npos) << message;
        EXPECT_NE(message.find("limit of 1 MB"), std::string::npos) << message;
    }
    EXPECT_EQ(budget.charged_bytes(), 600'000u);  // a refused charge is not counted
    budget.charge(400'000, "exactly the rest");
    EXPECT_EQ(budget.charged_bytes(), 1'000'000u);
}

TEST(MemoryBudget, HugeEstimatesDoNotWrapAround) {
    MemoryBudget budget(std::numeric_limits<std::uint64_t>::max() - 1);
    budget.charge(10, "small");
    EXPECT_THROW(budget.charge(std::numeric_limits<std::uint64_t>::max(), "huge"), InputError);
    EXPECT_EQ(saturating_product({65536, 65536, 1u << 20, 1u << 20}), std::numeric_limits<std::uint64_t>::max());
    EXPECT_EQ(saturating_product({65536, 65536, 88}), 65536ull * 65536ull * 88ull);
}

TEST(MemoryBudget, DefaultLimitIsFourFifthsOfPhysicalMemory) {
    const std::uint64_t physical = MemoryBudget::physical_memory_bytes();
    ASSERT_GT(physical, 0u);
    EXPECT_EQ(MemoryBudget().limit_bytes(), physical / 5 * 4);
}

// Working memory freed again does not count against what comes after it.
TEST(MemoryBudget, AReservationIsGivenBackWhenItEnds) {
    MemoryBudget budget(100);
    {
        const MemoryReservation working(budget, 80, "working memory");
        EXPECT_EQ(budget.charged_bytes(), 80u);
        EXPECT_THROW(budget.charge(30, "more"), InputError);
        MemoryReservation moved = MemoryReservation(budget, 10, "a little more");
        EXPECT_EQ(budget.charged_bytes(), 90u);
    }
    EXPECT_EQ(budget.charged_bytes(), 0u);
    budget.charge(90, "afterwards");
    EXPECT_THROW(MemoryReservation(budget, 20, "too much"), InputError);
    EXPECT_EQ(budget.charged_bytes(), 90u);  // a refused reservation gives back nothing it did not take
}

TEST(MemoryBudget, FormatsBytesWithThreeSignificantDigits) {
    EXPECT_EQ(format_bytes(512), "512 bytes");
    EXPECT_EQ(format_bytes(27'400'000'000ull), "27.4 GB");
    EXPECT_EQ(format_bytes(1'500'000), "1.5 MB");
}

}  // namespace
}  // namespace isotrace
