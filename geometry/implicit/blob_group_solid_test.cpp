// A blob group as a CSG operand: the spans of a ray inside the surface (F > T), against closed forms for a lone
// metaball and against dense sampling of the summed field for a random group. Also: the per-ray cache of the
// Embree queries gives the same nearest hit whatever order the elements are asked in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "geometry/implicit/blob_group_shape.h"
#include "geometry/implicit/implicit_test_support.h"
#include "geometry/sphere/sphere_intersection.h"

namespace isotrace {
namespace {

BlobGroupShape lone_ball(const Vec3d& centre, double radius) {
    return BlobGroupShape(BlobGroup({Metacube::metaball(centre, radius, 1.0)}, make_field_function("kim", 4.0), 0.5));
}

double total_field(const BlobGroup& group, const Vec3d& p) {
    double sum = -group.threshold();
    for (const Metacube& element : group.elements()) sum += element.field(group.kernel(), p);
    return sum;
}

TEST(BlobGroupSolid, LoneMetaballGivesOneSpanBetweenTheSphereHits) {
    const Vec3d centre(0.2, -0.1, 0.3);
    const BlobGroupShape shape = lone_ball(centre, 1.2);
    const double iso = *shape.group().kernel().iso_radius(1.2, 1.0, 0.5);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(-1, 1);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3d origin = centre + normalize(Vec3d(unit(random), unit(random), unit(random))) * 5.0;
        const Vec3d direction = (centre + Vec3d(unit(random), unit(random), unit(random)) * iso - origin) * 0.6;
        std::vector<InsideSpan> spans;
        shape.inside_spans(origin, direction, 0, 100, spans);
        const auto expected = intersect_sphere(origin, direction, centre, iso);
        if (!expected || expected->t1 - expected->t0 < 1e-6) {
            EXPECT_TRUE(spans.empty() || spans[0].exit.t - spans[0].enter.t < 1e-5) << i;
            continue;
        }
        ++hits;
        ASSERT_EQ(spans.size(), 1u) << i;
        EXPECT_NEAR(spans[0].enter.t, expected->t0, 1e-7) << i;
        EXPECT_NEAR(spans[0].exit.t, expected->t1, 1e-7) << i;
        ASSERT_TRUE(spans[0].enter.on_surface() && spans[0].exit.on_surface());
        const Vec3d p0 = origin + direction * spans[0].enter.t, p1 = origin + direction * spans[0].exit.t;
        EXPECT_NEAR(dot(spans[0].enter.normal, normalize(p0 - centre)), 1.0, 1e-6);
        EXPECT_NEAR(dot(spans[0].exit.normal, normalize(p1 - centre)), 1.0, 1e-6);
    }
    EXPECT_GT(hits, 150);
}

TEST(BlobGroupSolid, RayFromInsideStartsWithACut) {
    const BlobGroupShape shape = lone_ball({0, 0, 0}, 1.0);
    const double iso = *shape.group().kernel().iso_radius(1.0, 1.0, 0.5);
    std::vector<InsideSpan> spans;
    shape.inside_spans({0.1, 0, 0}, {2, 0, 0}, -0.2, 10, spans);  // starts at x = -0.3, inside
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_FALSE(spans[0].enter.on_surface());
    EXPECT_EQ(spans[0].enter.t, -0.2);
    EXPECT_NEAR(spans[0].exit.t, (iso - 0.1) / 2, 1e-9);
    // Cut at the far end too when the range stops inside.
    spans.clear();
    shape.inside_spans({-3, 0, 0}, {1, 0, 0}, 0, 3, spans);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_NEAR(spans[0].enter.t, 3 - iso, 1e-9);
    EXPECT_FALSE(spans[0].exit.on_surface());
    EXPECT_EQ(spans[0].exit.t, 3);
}

// Every span end is a sign change of the summed field found by dense sampling, and the field is positive inside
// the spans and negative between them.
TEST(BlobGroupSolid, SpansOfARandomGroupMatchDenseSampling) {
    const BlobGroupShape shape(random_blob_group(60, 8, "wyvill", 7));
    const BlobGroup& group = shape.group();
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    int spans_seen = 0;
    for (int ray = 0; ray < 60; ++ray) {
        const Vec3d origin(unit(random) * 1.5, unit(random) * 1.5, 4.0);
        const Vec3d direction = normalize(Vec3d(unit(random) * 0.3, unit(random) * 0.3, -1.0));
        std::vector<InsideSpan> spans;
        shape.inside_spans(origin, direction, 0, 8, spans);
        std::vector<double> reference;  // sign changes by sampling every 5e-4 and bisecting
        const double step = 5e-4;
        double previous = total_field(group, origin);
        for (double t = step; t <= 8; t += step) {
            const double value = total_field(group, origin + direction * t);
            if ((value > 0) != (previous > 0)) {
                double lo = t - step, hi = t;
                for (int i = 0; i < 60; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    ((total_field(group, origin + direction * mid) > 0) == (previous > 0) ? lo : hi) = mid;
                }
                reference.push_back(0.5 * (lo + hi));
            }
            previous = value;
        }
        ASSERT_EQ(2 * spans.size(), reference.size()) << "ray " << ray;
        for (std::size_t k = 0; k < spans.size(); ++k) {
            EXPECT_NEAR(spans[k].enter.t, reference[2 * k], 1e-6) << "ray " << ray;
            EXPECT_NEAR(spans[k].exit.t, reference[2 * k + 1], 1e-6) << "ray " << ray;
            const double middle = 0.5 * (spans[k].enter.t + spans[k].exit.t);
            EXPECT_GT(total_field(group, origin + direction * middle), 0);
            // The entry normal faces against the ray, the exit normal along it.
            EXPECT_LT(dot(spans[k].enter.normal, direction), 0);
            EXPECT_GT(dot(spans[k].exit.normal, direction), 0);
            ++spans_seen;
        }
    }
    EXPECT_GT(spans_seen, 30);
}

// Embree asks the cells in its own order while t_far shrinks: the nearest hit must not depend on that order, and
// must be the first of all crossings.
TEST(BlobGroupSolid, NearestHitDoesNotDependOnTheOrderOfCellQueries) {
    const BlobGroup group = random_blob_group(80, 12, "wyvill", 7);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<std::uint32_t> order(group.cells().cells().size());
    std::iota(order.begin(), order.end(), 0);
    int hits = 0;
    for (int ray = 0; ray < 120; ++ray) {
        const Vec3d origin(unit(random) * 1.8, unit(random) * 1.8, 4.0);
        const Vec3d direction(unit(random) * 0.2, unit(random) * 0.2, -1.0);
        std::vector<FieldCrossing> all;
        BlobQueryWork work;
        group.crossings(origin, direction, 0, 10, all, work);
        const std::optional<double> expected = all.empty() ? std::nullopt : std::optional(all.front().t);
        for (int trial = 0; trial < 4; ++trial) {
            std::shuffle(order.begin(), order.end(), random);
            std::optional<double> best;
            for (std::uint32_t cell : order)
                if (const auto c = group.first_crossing_in_cell(cell, origin, direction, 0, best.value_or(1e30), work))
                    best = c->t;
            ASSERT_EQ(best.has_value(), expected.has_value()) << "ray " << ray << " trial " << trial;
            if (best) {
                EXPECT_NEAR(*best, *expected, 1e-9) << "ray " << ray << " trial " << trial;
            }
        }
        hits += expected.has_value();
    }
    EXPECT_GT(hits, 40);
}

}  // namespace
}  // namespace isotrace
