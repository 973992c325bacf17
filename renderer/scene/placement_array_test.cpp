#include "renderer/scene/placement_array.h"

#include <gtest/gtest.h>

#include <cmath>

namespace isotrace {
namespace {

TEST(PlacementRecord, KeepsTheTransformToSinglePrecision) {
    const Transform to_world = Transform::translate({3, -2, 100}) * Transform::rotate({1, 2, 3}, 40) *
                               Transform::scale({0.7, 1.3, 2});
    const auto record = placement_record(to_world, 5);
    ASSERT_TRUE(record);
    EXPECT_EQ(record->variant, 5u);
    EXPECT_EQ(sizeof(PlacementRecord), 52u) << "a placement's record is what it costs besides Embree";
    const Transform back = to_world_of_record(*record);
    // The record holds the inverse, whose translation is rounded at its own size: carried back, that is the
    // translation's size times the condition number, in float roundings.
    const double translation = length(Vec3d(to_world.matrix()[0][3], to_world.matrix()[1][3], to_world.matrix()[2][3]));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(back.matrix()[i][j], to_world.matrix()[i][j],
                        j < 3 ? 2e-7 : 1.2e-7 * to_world.condition_number() * translation);
    // The same bits on every call: every hit on the placement is shaded with the same transform.
    EXPECT_EQ(to_world_of_record(*record).matrix(), back.matrix());
}

TEST(PlacementRecord, IsRefusedWhenRoundingMakesItSingular) {
    // Regular in double (determinant 1e-9), singular once its inverse's entries of about 1e9 are rounded to float.
    const Transform nearly_flat =
        Transform::from_matrix({{{1, 1, 0, 0}, {1, 1 + 1e-9, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
    EXPECT_FALSE(placement_record(nearly_flat, 0));
}

TEST(PlacementNames, AreIndexedUnlessNamedAndEndInThePart) {
    PlacementNames names{"herd", "/head", {{2, "leader"}, {7, "last"}}};
    EXPECT_EQ(names.of(0), "herd[0]/head");
    EXPECT_EQ(names.of(2), "leader/head");
    EXPECT_EQ(names.of(3), "herd[3]/head");
    EXPECT_EQ(names.of(7), "last/head");
    EXPECT_EQ(names.of(8), "herd[8]/head");
}

}  // namespace
}  // namespace isotrace
