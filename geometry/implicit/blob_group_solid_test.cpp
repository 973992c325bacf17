// A blob group as a CSG operand: the spans of a ray inside the surface (F > T), against closed forms for a lone
// metaball and against dense sampling of the summed field for a random group; hard cubes among metacubes entered
// and left in turn. Also: the nearest hit does not depend on the order in which Embree offers the cells.
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
        const Vec3d origin = centre + normalize(Vec3d{unit(random), unit(random), unit(random)}) * 5.0;
        const Vec3d direction = (centre + Vec3d{unit(random), unit(random), unit(random)} * iso - origin) * 0.6;
        std::vector<InsideSpan> spans;
        QueryScratch scratch;
        shape.inside_spans(origin, direction, 0, 100, spans, scratch);
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
    QueryScratch scratch;
    shape.inside_spans({0.1, 0, 0}, {2, 0, 0}, -0.2, 10, spans, scratch);  // starts at x = -0.3, inside
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_FALSE(spans[0].enter.on_surface());
    EXPECT_EQ(spans[0].enter.t, -0.2);
    EXPECT_NEAR(spans[0].exit.t, (iso - 0.1) / 2, 1e-9);
    // Cut at the far end too when the range stops inside.
    spans.clear();
    shape.inside_spans({-3, 0, 0}, {1, 0, 0}, 0, 3, spans, scratch);
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
        const Vec3d origin{unit(random) * 1.5, unit(random) * 1.5, 4.0};
        const Vec3d direction = normalize(Vec3d{unit(random) * 0.3, unit(random) * 0.3, -1.0});
        std::vector<InsideSpan> spans;
        QueryScratch scratch;
        shape.inside_spans(origin, direction, 0, 8, spans, scratch);
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

// Groups of hard cubes (radius 0: the box itself, F steps at its faces) and metacubes, some carving (w < 0), half
// of them axis-aligned on a quarter grid, and rays from outside or from among the elements, half of them
// axis-aligned on the same grid (as cameras meet such boxes). Every ray's crossings enter and leave in turn from
// the side it starts on and end outside; F has the expected side just before and after each; the nearest hit is
// the first crossing and occlusion is their existence. Hard cubes' faces often lie on cell faces and on the group's
// bounds: a lone cube's exit was missed on every ray once.
TEST(BlobGroupSolid, HardCubesAmongMetacubesAreEnteredAndLeftInTurn) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0, 1);
    const auto on_grid = [](const Vec3d& v) {
        return Vec3d(std::round(v.x * 4) / 4, std::round(v.y * 4) / 4, std::round(v.z * 4) / 4);
    };
    const char* kernels[] = {"kim", "wyvill", "murakami", "nishimura", "blinn"};
    int rays = 0, out_of_turn = 0, wrong_side = 0, wrong_first = 0, wrong_occlusion = 0;
    for (int g = 0; g < 300; ++g) {
        std::vector<Metacube> elements;
        const int count = 1 + int(u(rng) * 5);
        for (int e = 0; e < count; ++e) {
            OrientedBox box;
            box.centre = random_vector(rng, -1.5, 1.5);
            if (u(rng) < 0.2) box.axes = random_axes(rng);
            if (u(rng) < 0.5) box.centre = on_grid(box.centre);
            for (int k = 0; k < 3; ++k)
                box.half_size[k] = u(rng) < 0.5 ? 0.25 * (1 + int(u(rng) * 3)) : 0.2 + 0.8 * u(rng);
            const double radius = u(rng) < 0.5 ? 0.0 : 0.3 + u(rng);
            const double weight = u(rng) < 0.3 ? -0.7 : 1.0;
            elements.emplace_back(box, radius, weight);
        }
        const BlobGroup group(elements, make_field_function(kernels[g % 5], 4.0), 0.5);
        for (int r = 0; r < 200; ++r) {
            Vec3d origin = normalize(random_vector(rng, -1, 1)) * 10.0;
            Vec3d direction = normalize(random_vector(rng, -1.5, 1.5) - origin);
            if (r % 2 == 0) {
                const int axis = r / 2 % 3;
                origin = random_vector(rng, -2, 2);
                if (r % 4 == 0) origin = on_grid(origin);
                origin[axis] = r % 8 < 4 ? -10 : 10;
                direction = Vec3d(0, 0, 0);
                direction[axis] = r % 8 < 4 ? 1 : -1;
            }
            ++rays;
            double t_min = 0;
            if (r % 3 == 0) t_min = 10 - 2 * u(rng);  // starts among the elements
            std::vector<FieldCrossing> crossings;
            BlobQueryWork work;
            const int start_sign = group.crossings(origin, direction, t_min, 30, crossings, work);
            const bool starts_inside = start_sign > 0;
            bool in_turn = crossings.size() % 2 == (starts_inside ? 1u : 0u);
            for (std::size_t i = 0; i < crossings.size(); ++i)
                in_turn = in_turn && crossings[i].entering == ((i % 2 == 0) != starts_inside);
            if (!in_turn && out_of_turn < 5) {
                std::string list;
                for (const auto& c : crossings) list += " " + std::to_string(c.t) + (c.entering ? "in" : "out");
                ADD_FAILURE() << "g " << g << " r " << r << " tmin " << t_min << " start " << start_sign << ":" << list;
            }
            if (!in_turn) ++out_of_turn;
            for (const FieldCrossing& c : crossings) {
                const double step = 1e-7 * (1 + c.t);
                const bool inside_before = group.field(origin + direction * (c.t - step)) > 0.5;
                const bool inside_after = group.field(origin + direction * (c.t + step)) > 0.5;
                if (inside_before == c.entering || inside_after != c.entering) ++wrong_side;
            }
            const auto first = group.first_crossing(origin, direction, t_min, 30, work);
            if (first.has_value() != !crossings.empty() ||
                (first && std::abs(first->t - crossings[0].t) > 1e-9 * (1 + first->t)))
                ++wrong_first;
            const bool occluded = occluded_in_any_cell(group, origin, direction, t_min, 30, work);
            if (occluded != !crossings.empty()) ++wrong_occlusion;
        }
    }
    EXPECT_EQ(rays, 60000);
    EXPECT_EQ(out_of_turn, 0);
    EXPECT_EQ(wrong_side, 0);
    EXPECT_EQ(wrong_first, 0);
    EXPECT_EQ(wrong_occlusion, 0);
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
        const Vec3d origin{unit(random) * 1.8, unit(random) * 1.8, 4.0};
        const Vec3d direction{unit(random) * 0.2, unit(random) * 0.2, -1.0};
        std::vector<FieldCrossing> all;
        BlobQueryWork work;
        group.crossings(origin, direction, 0, 10, all, work);
        const std::optional<double> expected = all.empty() ? std::nullopt : std::optional(all.front().t);
        for (int trial = 0; trial < 4; ++trial) {
            std::shuffle(order.begin(), order.end(), random);
            std::optional<double> best;
            for (std::uint32_t cell : order)
                if (const auto c = group.queries().first_hit_in_cell(group, cell, origin, direction, 0,
                                                                     best.value_or(1e30), work))
                    best = c->crossing.t;
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
