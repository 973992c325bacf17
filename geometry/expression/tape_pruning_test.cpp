// Tape pruning: over a box where interval arithmetic settles a min, max or |·|, the pruned tape is shorter, gives
// the whole tape's point values inside the box, and its intervals hold them.
#include "geometry/expression/tape_pruning.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/expression/expression_field.h"

namespace isotrace {
namespace {

std::shared_ptr<const ExpressionField> compile(const std::string& text) {
    return compile_expression({text, {"scene.json", 1, 1}, "f"}, {});
}

const char* const kSmoothUnion =
    "smin(smin(length(max(abs(p - vec(0, 0.35, 0)) - vec(0.45, 0.3, 0.45), 0)) - 0.05, length(p - vec(0, 0.95, 0)) "
    "- 0.38, 0.2), max(length(vec(x - 0.45, 0, z)) - 0.12, abs(y - 0.9) - 0.5), 0.15)";

// The pruned field over `box` against the whole one at random points of the box (and of sub-boxes).
void expect_same_inside(const ExpressionField& whole, const IntervalBox& box, std::uint64_t seed) {
    const std::shared_ptr<const ExpressionField> pruned = whole.pruned(whole.settled_choices(box));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto inside = [&] {
        return Vec3d{box.x.lo + unit(rng) * box.x.width(), box.y.lo + unit(rng) * box.y.width(),
                     box.z.lo + unit(rng) * box.z.width()};
    };
    for (int i = 0; i < 2000; ++i) {
        const Vec3d p = inside(), q = inside();
        ASSERT_EQ(pruned->value(p), whole.value(p)) << p.x << " " << p.y << " " << p.z;
        IntervalBox sub = IntervalBox::point(p);
        sub.extend(q);
        const Interval range = pruned->value_range(sub);
        ASSERT_TRUE(range.contains(pruned->value(p)) && range.contains(pruned->value(q)));
        const Vec3d d = q - p;
        const double slope = whole.value_and_slope(p, d).derivative;
        ASSERT_TRUE(pruned->slope_range(sub, d).contains(slope)) << slope;
    }
}

TEST(TapePruning, SettlesMinMaxAndAbsWhereTheOperandsSeparate) {
    const auto f = compile("min(x, 2) + max(y, 3) + abs(z) + abs(x - 5)");
    const std::vector<std::uint8_t> choices = f->settled_choices({{0, 1}, {0, 1}, {-2, -1}});
    const auto pruned = f->pruned(choices);
    // min → x, max → 3, |z| → −z, |x − 5| → −(x − 5): four instructions fewer, no min, max or abs left.
    EXPECT_LT(pruned->tape_length(), f->tape_length());
    EXPECT_EQ(pruned->value({0.5, 0.5, -1.5}), 0.5 + 3 + 1.5 + 4.5);
    // Nothing settled over a box where the operands overlap.
    const std::vector<std::uint8_t> none = f->settled_choices({{1, 3}, {2, 4}, {-1, 1}});
    EXPECT_EQ(f->pruned(none)->tape_length(), f->tape_length());
}

// A smooth blend folds to its min where |a − b| ≥ r over the box: its bend drops out with the far operand.
TEST(TapePruning, ASmoothUnionNearOnePartRunsThatPartAlone) {
    const auto f = compile(kSmoothUnion);
    const IntervalBox near_the_box_corner{{0.4, 0.45}, {0.0, 0.05}, {-0.5, -0.45}};
    const auto pruned = f->pruned(f->settled_choices(near_the_box_corner));
    EXPECT_LT(pruned->tape_length() * 2, f->tape_length());
    expect_same_inside(*f, near_the_box_corner, 1);
}

TEST(TapePruning, PointValuesAreTheWholeTapesInsideTheBox) {
    const std::vector<std::string> functions{
        kSmoothUnion,
        "max(abs(sqrt((cos(1.8*y)*x - sin(1.8*y)*z)^2 + y^2) - 0.62), abs(sin(1.8*y)*x + cos(1.8*y)*z)) - 0.2",
        "abs(sin(7*x)*cos(7*y) + sin(7*y)*cos(7*z) + sin(7*z)*cos(7*x)) - 0.35",
        "smax(length(p) - 1, -(length(p - vec(0.5, 0, 0)) - 0.6), 0.1) + 0.01*fbm(4*p)"};
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> corner(-1, 1), size(0.01, 0.2);
    for (std::size_t f = 0; f < functions.size(); ++f) {
        const auto field = compile(functions[f]);
        for (int i = 0; i < 20; ++i) {
            const Vec3d lower{corner(rng), corner(rng), corner(rng)};
            const double s = size(rng);
            expect_same_inside(*field, {{lower.x, lower.x + s}, {lower.y, lower.y + s}, {lower.z, lower.z + s}},
                               f * 100 + i);
        }
    }
}

}  // namespace
}  // namespace isotrace
