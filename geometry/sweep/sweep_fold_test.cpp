#include "geometry/sweep/sweep_fold.h"

#include <gtest/gtest.h>

#include "geometry/sweep/sweep_surface.h"
#include "geometry/sweep/sweep_test_support.h"

namespace isotrace {
namespace {

using sweep_test::constant_radii;

TEST(SweepFold, StraightAndGentlyBentSweepsAreSound) {
    EXPECT_EQ(sweep_fold(SweepSurface(sweep_test::cylinder(0.3, 2))), "");
    EXPECT_EQ(sweep_fold(SweepSurface(sweep_test::bent_tube())), "");
    EXPECT_EQ(sweep_fold(SweepSurface(sweep_test::ring(1, 180, 7, constant_radii(0.5)))), "");
}

TEST(SweepFold, BendingTighterThanTheRadiusFolds) {
    // A ring of radius 1 with sections of radius 1.5: the inner side of every section crosses the next one's.
    const std::string fold = sweep_fold(SweepSurface(sweep_test::ring(1, 180, 7, constant_radii(1.5))));
    EXPECT_NE(fold.find("cross"), std::string::npos) << fold;
}

TEST(SweepFold, SectionsOutOfOrderFold) {
    // The middle key pulled back behind the first: the axis turns back on itself.
    std::vector<KeySection> keys = sweep_test::cylinder(0.1, 2, 5);
    const std::vector<double> parameters = SweepSurface(keys).key_parameters();
    keys[2].centre = {0, 0, -0.5};
    EXPECT_NE(sweep_fold(SweepSurface(keys, parameters)), "");
}

TEST(SweepFold, StretchIsTheLargestLengthFactorEitherWay) {
    const SweepSurface original(sweep_test::cylinder(0.3, 2, 3));
    EXPECT_DOUBLE_EQ(sweep_stretch(original, original), 1);
    std::vector<KeySection> keys = original.keys();
    for (double& r : keys[1].radii) r /= 3;
    EXPECT_NEAR(sweep_stretch(original, SweepSurface(keys, original.key_parameters())), 3, 1e-12);
    keys = original.keys();
    for (KeySection& k : keys) k.centre = 1.5 * k.centre;
    EXPECT_NEAR(sweep_stretch(original, SweepSurface(keys, original.key_parameters())), 1.5, 1e-9);
}

}  // namespace
}  // namespace isotrace
