// The interval bounds of the shapes' fields that an isosurface may use as terms (spheres, boxes, blob groups,
// superquadrics, and any of them carried by a transform): over random boxes, every sampled value lies in
// value_range and every sampled slope along a random direction in slope_range; and they are tight enough to
// exclude zero away from the surface, which is what keeps a search through them fast.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "geometry/field/transformed_field.h"
#include "renderer/plugin/shape.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

std::unique_ptr<Shape> shape_from_json(const std::string& json) {
    const testing::ParsedScene parsed(json);
    return shape_registry().create(parsed.root());
}

// Samples boxes of sizes from 1e-3 to 1 around points of [−2, 2]³ and checks the bounds there; returns how many
// boxes had a value range that excludes zero.
int check_bounds(const ImplicitField& field, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> where(-2, 2), unit(0, 1);
    std::normal_distribution<double> normal;
    int excluding = 0;
    for (int b = 0; b < 400; ++b) {
        const double size = std::pow(10.0, -3 * unit(rng));
        const Vec3d lower{where(rng), where(rng), where(rng)};
        const IntervalBox box{{lower.x, lower.x + size}, {lower.y, lower.y + size}, {lower.z, lower.z + size}};
        const Vec3d d{normal(rng), normal(rng), normal(rng)};
        const Interval value = field.value_range(box), slope = field.slope_range(box, d);
        excluding += value.excludes_zero();
        for (int s = 0; s < 20; ++s) {
            const Vec3d p{box.x.lo + size * unit(rng), box.y.lo + size * unit(rng), box.z.lo + size * unit(rng)};
            const double f = field.value(p);
            const double tolerance = 1e-12 * (1 + std::abs(f));
            EXPECT_GE(f, value.lo - tolerance) << "box " << b;
            EXPECT_LE(f, value.hi + tolerance) << "box " << b;
            // The slope by a central difference, where both points are in the box.
            const double h = 1e-7 * size / length(d);
            if (!box.contains(p + d * h) || !box.contains(p - d * h)) continue;
            const double g = (field.value(p + d * h) - field.value(p - d * h)) / (2 * h);
            const double slack = 1e-4 * (1 + std::abs(g));
            EXPECT_GE(g, slope.lo - slack) << "box " << b;
            EXPECT_LE(g, slope.hi + slack) << "box " << b;
        }
    }
    return excluding;
}

TEST(FieldRanges, Spheres) {
    const auto shape = shape_from_json(
        R"({"type": "sphere", "spheres": [{"center": [0, 0, 0], "radius": 1}, {"center": [1, 0.5, 0], "radius": 0.6}]})");
    EXPECT_GT(check_bounds(*shape->implicit_field(), 1), 300);
}

TEST(FieldRanges, RotatedBox) {
    const auto shape = shape_from_json(
        R"({"type": "box", "center": [0.2, 0, 0], "half_size": [1, 0.5, 0.3]})");
    const auto field = transformed_field(shape->implicit_field(), Transform::rotate({1, 1, 0}, 30));
    EXPECT_GT(check_bounds(*field, 2), 300);
}

TEST(FieldRanges, BlobGroupOfMetaballsAndMetacubes) {
    const auto shape = shape_from_json(R"({"type": "blobs", "elements": [
        {"center": [0, 0, 0], "radius": 1.2},
        {"center": [0.8, 0.3, 0], "radius": 0.9, "weight": 0.8},
        {"center": [-0.5, 0.5, 0.5], "radius": 0.5, "weight": -0.4},
        {"center": [0, -0.8, 0], "radius": 0.6, "half_size": [0.3, 0.2, 0.1], "rotate": {"axis": [0, 0, 1], "angle": 20}}]})");
    EXPECT_GT(check_bounds(*shape->implicit_field(), 3), 250);
}

TEST(FieldRanges, DeformedSuperquadrics) {
    const auto shape = shape_from_json(R"({"type": "superquadric", "superquadrics": [
        {"radii": [1, 0.7, 0.5], "exponents": [0.5, 1.5], "deform": [{"twist": 90}, {"taper": 0.3}]},
        {"radii": [0.4, 0.4, 1], "exponents": [1, 1], "center": [1, 0, 0]}]})");
    EXPECT_GT(check_bounds(*shape->implicit_field(), 4), 250);
}

}  // namespace
}  // namespace isotrace
