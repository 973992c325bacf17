#include "renderer/math/line_box_clip.h"

#include <gtest/gtest.h>

#include <limits>

namespace isotrace {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
const Vec3d kLower{-1, -2, -3}, kUpper{1, 2, 3};

TEST(LineBoxClip, AxisRayEntersAndLeavesThroughFaces) {
    const auto clip = clip_line_to_box(kLower, kUpper, {-5, 0, 0}, {2, 0, 0}, -kInfinity, kInfinity);
    ASSERT_TRUE(clip);
    EXPECT_DOUBLE_EQ(clip->t_enter, 2);
    EXPECT_DOUBLE_EQ(clip->t_exit, 3);
    EXPECT_EQ(clip->enter_axis, 0);
    EXPECT_EQ(clip->exit_axis, 0);
}

TEST(LineBoxClip, DiagonalRayReportsTheLimitingAxes) {
    // Enters through y = −2 at t = 1 (x = −0.5), leaves through x = 1 at t = 2.5 (y = 1).
    const auto clip = clip_line_to_box(kLower, kUpper, {-1.5, -3, 0}, {1, 1, 0}, -kInfinity, kInfinity);
    ASSERT_TRUE(clip);
    EXPECT_DOUBLE_EQ(clip->t_enter, 1);
    EXPECT_EQ(clip->enter_axis, 1);
    EXPECT_DOUBLE_EQ(clip->t_exit, 2.5);
    EXPECT_EQ(clip->exit_axis, 0);
}

TEST(LineBoxClip, RangeLimitsTheClip) {
    const auto clip = clip_line_to_box(kLower, kUpper, {0, 0, 0}, {0, 0, 1}, 0, 1);
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->t_enter, 0);
    EXPECT_EQ(clip->t_exit, 1);
    EXPECT_EQ(clip->enter_axis, -1);
    EXPECT_EQ(clip->exit_axis, -1);
    EXPECT_FALSE(clip_line_to_box(kLower, kUpper, {0, 0, 0}, {0, 0, 1}, 4, 5));
}

TEST(LineBoxClip, ParallelLinesInsideOrOutsideTheSlab) {
    EXPECT_TRUE(clip_line_to_box(kLower, kUpper, {0, 1.5, -9}, {0, 0, 1}, -kInfinity, kInfinity));
    EXPECT_FALSE(clip_line_to_box(kLower, kUpper, {0, 2.5, -9}, {0, 0, 1}, -kInfinity, kInfinity));
    // Closed box: a line along a face is inside it.
    EXPECT_TRUE(clip_line_to_box(kLower, kUpper, {0, 2, -9}, {0, 0, 1}, -kInfinity, kInfinity));
}

TEST(LineBoxClip, TouchingACornerIsAPoint) {
    // Through the corner (1, 2) at t = 1, outside on both sides of it.
    const auto clip = clip_line_to_box(kLower, kUpper, {0, 3, 0}, {1, -1, 0}, -kInfinity, kInfinity);
    ASSERT_TRUE(clip);
    EXPECT_DOUBLE_EQ(clip->t_enter, 1);
    EXPECT_DOUBLE_EQ(clip->t_exit, 1);
    EXPECT_FALSE(clip_line_to_box(kLower, kUpper, {0.5, 3, 0}, {1, -1, 0}, -kInfinity, kInfinity));
}

}  // namespace
}  // namespace isotrace
