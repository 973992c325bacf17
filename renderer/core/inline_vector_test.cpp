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

// Values written past the end are kept by extend_to, across the move to the heap that room_for makes.
TEST(InlineVector, RoomForTakesValuesWrittenPastTheEnd) {
    InlineVector<int, 4> values;
    values.push_back(-1);
    int* room = values.room_for(10);
    for (int i = 0; i < 10; ++i) room[i] = i;
    values.extend_to(1 + 7);  // keep seven of the ten written
    ASSERT_EQ(values.size(), 8u);
    EXPECT_EQ(values[0], -1);
    for (int i = 0; i < 7; ++i) EXPECT_EQ(values[std::size_t(i) + 1], i);
    values.push_back(99);
    EXPECT_EQ(values.back(), 99);
}

}  // namespace
}  // namespace isotrace
