#include "renderer/core/inline_vector.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

TEST(InlineVector, KeepsValuesInOrderAcrossTheMoveToTheHeap) {
    InlineVector<int, 4> values;
    for (int i = 0; i < 100; ++i) values.push_back(i * i);
    ASSERT_EQ(values.size(), 100u);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(values[std::size_t(i)], i * i);
    int sum = 0;
    for (int v : values) sum += v;
    EXPECT_EQ(sum, 328350);
}

TEST(InlineVector, PushBackReturnsTheCopyAndClearEmpties) {
    InlineVector<double, 2> values;
    values.push_back(5) += 1;
    values.push_back(7);
    values.truncate(1);
    EXPECT_EQ(values.size(), 1u);
    EXPECT_EQ(values.back(), 6.0);
    values.clear();
    EXPECT_TRUE(values.empty());
}

}  // namespace
}  // namespace isotrace
