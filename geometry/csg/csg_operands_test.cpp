// CSG over the implicit primitives, built from the scene format as a user would write them: a superquadric and
// a blob group are solids like spheres and boxes, so shells and cuts of them have closed-form hit sequences.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/csg/csg_test_support.h"
#include "renderer/plugin/shape.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using csg_test::hit_sequence;
using csg_test::make_ray;
using csg_test::scene_of;

std::unique_ptr<Shape> shape_from_json(const std::string& json) {
    const testing::ParsedScene parsed(json);
    return shape_registry().create(parsed.root());
}

// A lone Kim metaball of radius 1 and weight 1 at threshold 0.5 is a sphere of this radius.
const double kMetaballIso = std::sqrt(1 - std::cbrt(0.5));

// Unit superquadric ellipsoid (ε1 = ε2 = 1) minus the metaball: a spherical shell of radii kMetaballIso and 1.
TEST(CsgOperands, SuperquadricMinusBlobGroupIsAShell) {
    const auto scene = scene_of(shape_from_json(R"({"type": "csg", "op": "difference", "children": [
        {"shape": {"type": "superquadric", "radii": [1, 1, 1], "exponents": [1, 1]}},
        {"shape": {"type": "blobs", "elements": [{"center": [0, 0, 0], "radius": 1}]}}]})"));
    // Slightly off the axis, so that no coordinate plane of the superquadric holds the ray.
    const Vec3d origin(0.11, 0.07, 3), direction(0, 0, -1);
    const double offset2 = 0.11 * 0.11 + 0.07 * 0.07;
    const double outer = std::sqrt(1 - offset2), inner = std::sqrt(kMetaballIso * kMetaballIso - offset2);
    const auto hits = hit_sequence(*scene, make_ray(origin, direction));
    ASSERT_EQ(hits.size(), 4u);
    const double expected[] = {3 - outer, 3 - inner, 3 + inner, 3 + outer};
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(hits[std::size_t(k)].t, expected[k], 2e-5) << "hit " << k;
        const Vec3d p = origin + direction * expected[k];
        // Outer surface: outward from the centre; inner surface (subtracted metaball): towards the centre.
        const Vec3d outward = normalize(p) * (k == 1 || k == 2 ? -1.0 : 1.0);
        EXPECT_GT(dot(Vec3d(hits[std::size_t(k)].geometric_normal), outward), 0.999) << "hit " << k;
    }
}

// A metaball cut by a box above z = 0 leaves the lower half: the cut face is flat, at z = 0, facing +z.
TEST(CsgOperands, BlobGroupCutByABoxHasAFlatFace) {
    const auto scene = scene_of(shape_from_json(R"({"type": "csg", "op": "difference", "children": [
        {"shape": {"type": "blobs", "elements": [{"center": [0, 0, 0], "radius": 1}]}},
        {"shape": {"type": "box", "center": [0, 0, 1], "half_size": [2, 2, 1]}}]})"));
    const auto down = hit_sequence(*scene, make_ray({0.2, 0.1, 3}, {0, 0, -1}));
    ASSERT_EQ(down.size(), 2u);
    EXPECT_NEAR(down[0].t, 3.0, 1e-5);
    EXPECT_GT(down[0].geometric_normal.z, 0.9999f);
    EXPECT_NEAR(down[1].t, 3 + std::sqrt(kMetaballIso * kMetaballIso - 0.05), 2e-5);
    // From the side above the cut, the ray misses; below it, it meets the sphere.
    EXPECT_TRUE(hit_sequence(*scene, make_ray({-3, 0, 0.1}, {1, 0, 0})).empty());
    EXPECT_EQ(hit_sequence(*scene, make_ray({-3, 0, -0.1}, {1, 0, 0})).size(), 2u);
}

// A sphere minus a slab that is a lone hard cube (radius 0): the slab's cell is the slab itself, so its exit face
// lies on the cell's far end. Before the sweep reported a hard cube's exit at a stretch's end, the slab was
// entered and never left: everything beyond it vanished, the lower part's cut face included (a visible gap).
TEST(CsgOperands, SphereMinusAHardCubeSlabKeepsBothCutFaces) {
    const auto scene = scene_of(shape_from_json(R"({"type": "csg", "op": "difference", "children": [
        {"shape": {"type": "sphere", "radius": 1.2}},
        {"shape": {"type": "blobs",
                   "elements": [{"center": [0, 0.2, 0], "half_size": [2, 0.25, 2], "radius": 0}]}}]})"));
    // Straight down, off the axis: the upper cap, its cut face at y = 0.45, then the lower part's at y = −0.05 and
    // the sphere's bottom.
    const double x = 0.3, z = 0.2, r2 = 1.2 * 1.2 - x * x - z * z;
    const auto hits = hit_sequence(*scene, make_ray({x, 3, z}, {0, -1, 0}));
    ASSERT_EQ(hits.size(), 4u);
    const double expected[] = {3 - std::sqrt(r2), 3 - 0.45, 3 + 0.05, 3 + std::sqrt(r2)};
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(hits[std::size_t(k)].t, expected[k], 1e-6) << "hit " << k;
    EXPECT_LT(hits[1].geometric_normal.y, -0.9999f);  // the cap's cut face looks down into the slab
    EXPECT_GT(hits[2].geometric_normal.y, 0.9999f);   // the lower part's looks up
}

// Shadow rays see the same solid: occluded exactly when a nearest hit exists inside the interval.
TEST(CsgOperands, OcclusionAgreesWithNearestHitsForImplicitOperands) {
    const auto scene = scene_of(shape_from_json(R"({"type": "csg", "op": "intersection", "children": [
        {"shape": {"type": "superquadric", "radii": [1.2, 0.8, 1], "exponents": [0.3, 2.5]}},
        {"shape": {"type": "blobs", "elements": [{"center": [-0.4, 0, 0], "radius": 1.1},
                                                  {"center": [0.5, 0.2, 0], "radius": 0.9, "half_size": 0.2}]}}]})"));
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const double u = (i % 20) / 19.0 - 0.5, v = (i / 20) / 19.0 - 0.5;
        const Ray ray = make_ray({3 * u, 3 * v, 4}, {0.05 * u, -0.03, -1}, 0, 10);
        const bool hit = scene->intersect(ray, RayKind::Camera).has_value();
        EXPECT_EQ(scene->occluded(ray), hit) << i;
        hits += hit;
    }
    EXPECT_GT(hits, 40);
}

}  // namespace
}  // namespace isotrace
