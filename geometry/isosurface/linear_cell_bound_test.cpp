// The linear model of a field over a cell: it holds the field on every segment of its cell (smooth functions,
// creases, a function whose slope is unbounded), and it settles a ray that passes a cell of the surface by
// without a run of the field's interval evaluation.
#include "geometry/isosurface/linear_cell_bound.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/expression/expression_field.h"
#include "geometry/isosurface/isosurface_test_support.h"

namespace isotrace {
namespace {

using isosurface_test::isosurface;
using isosurface_test::SphereField;
using isosurface_test::unit_box;

std::shared_ptr<const ImplicitField> expression(const std::string& text) {
    return compile_expression({text, {"scene.json", 1, 1}, "f"}, {});
}

// Random segments in random cells (of a 32³ grid over [−1, 1]³) that the field's interval says may hold its
// surface: the model's interval holds f at 64 points of each.
void expect_holds_the_field(const ImplicitField& field, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> cell_index(0, 31);
    std::uniform_real_distribution<double> unit(0, 1);
    int segments = 0;
    for (int attempt = 0; attempt < 20000 && segments < 400; ++attempt) {
        const Vec3d lower = Vec3d{double(cell_index(rng)), double(cell_index(rng)), double(cell_index(rng))} / 16.0 -
                            Vec3d{1, 1, 1};
        const IntervalBox cell{{lower.x, lower.x + 0.0625}, {lower.y, lower.y + 0.0625}, {lower.z, lower.z + 0.0625}};
        if (field.value_range(cell).excludes_zero()) continue;
        ++segments;
        const LinearCellBound model = LinearCellBound::of(field, cell);
        const auto inside = [&] {
            return lower + Vec3d{unit(rng), unit(rng), unit(rng)} * 0.0625;
        };
        const Vec3d a = inside(), b = inside();
        const Interval bound = model.over_segment(a, b);
        for (int i = 0; i <= 64; ++i) {
            const Vec3d p = a + (b - a) * (i / 64.0);
            ASSERT_TRUE(bound.contains(field.value(p))) << "cell at " << lower.x << ", " << lower.y << ", " << lower.z
                                                        << ": " << field.value(p) << " not in [" << bound.lo << ", "
                                                        << bound.hi << "]";
        }
    }
    EXPECT_EQ(segments, 400);
}

TEST(LinearCellBound, HoldsTheFieldOnEverySegmentOfItsCell) {
    expect_holds_the_field(*expression("sin(7*x)*cos(7*y) + sin(7*y)*cos(7*z) + sin(7*z)*cos(7*x)"), 1);
    expect_holds_the_field(*expression("abs(sin(7*x)*cos(7*y) + sin(7*y)*cos(7*z) + sin(7*z)*cos(7*x)) - 0.35"), 2);
    // Creases where the gradient jumps (max, abs, min of distances).
    expect_holds_the_field(*expression("max(abs(sqrt((cos(1.8*y)*x - sin(1.8*y)*z)^2 + y^2) - 0.62), "
                                       "abs(sin(1.8*y)*x + cos(1.8*y)*z)) - 0.2"),
                           3);
    expect_holds_the_field(*expression("smin(length(max(abs(p) - vec(0.4, 0.3, 0.4), 0)) - 0.05, "
                                       "length(p - vec(0, 0.6, 0)) - 0.38, 0.2)"),
                           4);
    // A slope the interval cannot bound (atan2's cut): the model bounds nothing there, and holds.
    expect_holds_the_field(*expression("atan2(y, x) - 3"), 5);
    expect_holds_the_field(SphereField(0.8), 6);
}

// A ray passing 0.01 outside a unit sphere goes through cells that hold the surface; their models settle it
// without an interval evaluation (each cell used to cost one).
TEST(LinearCellBound, SettlesARayThatPassesTheSurfaceBy) {
    const auto shape = isosurface(std::make_unique<SphereField>(1), unit_box(1.5));
    const Vec3d o{-3, 1.01, 0}, d{1, 0, 0};
    int cells_crossed = 0;
    std::uint64_t interval_bounds = 0;
    for (std::uint32_t cell = 0; cell < shape->cells().size(); ++cell) {
        const IntervalBox& box = shape->cells()[cell];
        if (!(box.y.contains(o.y) && box.z.contains(o.z))) continue;
        ++cells_crossed;
        IsosurfaceWork work;
        EXPECT_FALSE(shape->first_hit(cell, o, d, 0, INFINITY, work));
        interval_bounds += work.search.interval_bounds;
    }
    EXPECT_GT(cells_crossed, 4);
    EXPECT_EQ(interval_bounds, 0u);
    // The same ray 0.01 inside still hits, where the sphere is.
    const Vec3d inside{-3, 0.99, 0};
    IsosurfaceWork work;
    const auto hit = shape->first_hit(std::uint32_t(-1), inside, d, 0, INFINITY, work);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3 - std::sqrt(1 - 0.99 * 0.99), 1e-12);
}

}  // namespace
}  // namespace isotrace
