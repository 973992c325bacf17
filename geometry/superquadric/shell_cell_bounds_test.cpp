// A shell cell's bounds of g over a segment: for random gradient bounds, centres and segments, the range holds every
// linear field whose gradient lies within the bounds, at points along the segment, and it is never wider than the
// interval product of the gradient's bounds with the box around the segment (the bound it replaced). A segment across
// which the gradient is nearly known is bounded nearly exactly.
#include "geometry/superquadric/shell_cell_bounds.h"

#include <gtest/gtest.h>

#include <random>

namespace isotrace {
namespace {

ShellCellBounds random_bounds(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(-1, 1), width(0, 2);
    ShellCellBounds bounds;
    bounds.known = true;
    bounds.value = 0.1 * unit(random);
    bounds.centre = {unit(random), unit(random), unit(random)};
    for (int k = 0; k < 3; ++k) {
        const double lo = 3 * unit(random);
        bounds.gradient[k] = {lo, lo + width(random)};
    }
    return bounds;
}

// What the cell bounds gave before: value + Σ ∂ₖg · (the segment's extent along k − centreₖ), in intervals.
Interval interval_product_range(const ShellCellBounds& bounds, const Vec3d& a, const Vec3d& b) {
    Interval g = Interval::point(bounds.value);
    for (int k = 0; k < 3; ++k)
        g = g + bounds.gradient[k] * (Interval::spanning(a[k], b[k]) + -bounds.centre[k]);
    return g;
}

TEST(ShellCellBounds, RangeHoldsEveryLinearFieldWithinTheGradientBounds) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1);
    for (int i = 0; i < 2000; ++i) {
        const ShellCellBounds bounds = random_bounds(random);
        const Vec3d a = bounds.centre + Vec3d{unit(random), unit(random), unit(random)} * 0.05;
        const Vec3d b = bounds.centre + Vec3d{unit(random), unit(random), unit(random)} * 0.05;
        const Interval range = bounds.range(a, b);
        for (int j = 0; j < 20; ++j) {
            Vec3d gradient;
            for (int k = 0; k < 3; ++k)
                gradient[k] = bounds.gradient[k].lo + bounds.gradient[k].width() * (j < 8 ? double(j >> k & 1) : fraction(random));
            const Vec3d p = a + (b - a) * fraction(random);
            const double g = bounds.value + dot(gradient, p - bounds.centre);
            EXPECT_TRUE(range.contains(g)) << i << " " << j;
        }
    }
}

// Over a whole box around the centre: every linear field within the bounds, at every corner (where its extremes lie)
// and at random points; and exactly the interval product there, the box being the segments' worst case.
TEST(ShellCellBounds, RangeOverABoxHoldsEveryLinearFieldWithinTheGradientBounds) {
    std::mt19937 random(13);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1), half(0.001, 0.05);
    for (int i = 0; i < 2000; ++i) {
        const ShellCellBounds bounds = random_bounds(random);
        IntervalBox box;
        for (int k = 0; k < 3; ++k) box[k] = {bounds.centre[k] - half(random), bounds.centre[k] + half(random)};
        const Interval range = bounds.range(box);
        for (int j = 0; j < 24; ++j) {
            Vec3d gradient, p;
            for (int k = 0; k < 3; ++k) {
                gradient[k] = bounds.gradient[k].lo + bounds.gradient[k].width() * (j < 8 ? double(j >> k & 1) : fraction(random));
                p[k] = box[k].lo + box[k].width() * (j < 16 ? double((j + i) >> k & 1) : fraction(random));
            }
            EXPECT_TRUE(range.contains(bounds.value + dot(gradient, p - bounds.centre))) << i << " " << j;
        }
        const Interval product = interval_product_range(bounds, box.lower(), box.upper());
        EXPECT_NEAR(range.lo, product.lo, 1e-11) << i;
        EXPECT_NEAR(range.hi, product.hi, 1e-11) << i;
    }
}

TEST(ShellCellBounds, RangeIsNeverWiderThanTheIntervalProduct) {
    std::mt19937 random(12);
    std::uniform_real_distribution<double> unit(-1, 1);
    int tighter = 0;
    for (int i = 0; i < 2000; ++i) {
        const ShellCellBounds bounds = random_bounds(random);
        const Vec3d a = bounds.centre + Vec3d{unit(random), unit(random), unit(random)} * 0.05;
        const Vec3d b = bounds.centre + Vec3d{unit(random), unit(random), unit(random)} * 0.05;
        const Interval range = bounds.range(a, b), product = interval_product_range(bounds, a, b);
        constexpr double kRounding = 1e-12;  // the range's allowance for the rounding of its products
        EXPECT_GE(range.lo, product.lo - 2 * kRounding) << i;
        EXPECT_LE(range.hi, product.hi + 2 * kRounding) << i;
        tighter += range.width() < product.width() - 1e-9;
    }
    EXPECT_GT(tighter, 1000);  // the linear part along the segment is exact, where the product takes each axis' worst end
}

TEST(ShellCellBounds, ANearlyKnownGradientBoundsTheSegmentNearlyExactly) {
    ShellCellBounds bounds;
    bounds.known = true;
    bounds.value = 0.25;
    bounds.centre = {0, 0, 0};
    bounds.gradient = {{1, 1 + 1e-9}, {-2, -2 + 1e-9}, {0.5, 0.5 + 1e-9}};
    const Vec3d a{-0.01, -0.01, 0.01}, b{0.01, 0.01, -0.01};
    const Interval range = bounds.range(a, b);
    // g = 0.25 + x − 2y + 0.5z: 0.265 at a, 0.235 at b.
    EXPECT_NEAR(range.lo, 0.235, 1e-10);
    EXPECT_NEAR(range.hi, 0.265, 1e-10);
    const Interval product = interval_product_range(bounds, a, b);
    EXPECT_NEAR(product.width(), 0.07, 1e-9);  // the per-axis product: more than twice as wide
}

}  // namespace
}  // namespace isotrace
