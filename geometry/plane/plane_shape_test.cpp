// The infinite plane through a real RenderScene: hit distances, normals and uv against closed forms (also for
// random rays in long double), grazing rays, far hits, baked affine placements and mirrors, the half-space's inside
// spans and a CSG cut, the signed-distance field, bounds that stay out of the scene's extent, and the scene format.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "geometry/csg/csg_test_support.h"
#include "geometry/plane/flat_shape_test_support.h"
#include "geometry/plane/plane_shape.h"
#include "geometry/sphere/sphere_shape.h"
#include "renderer/core/ray.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {
namespace {

using csg_test::expect_near;
using csg_test::make_ray;
using csg_test::scene_of;

std::unique_ptr<PlaneShape> plane(const Vec3d& point = {0, 0, 0}, const Vec3d& normal = {0, 1, 0},
                                  double uv_scale = 1) {
    return std::make_unique<PlaneShape>(point, normalize(normal), uv_scale);
}

TEST(PlaneShape, DefaultPlaneHitsFromBothSidesWithItsNormalAndUv) {
    const auto scene = scene_of(plane({0, 0, 0}, {0, 1, 0}, 2));
    const auto above = scene->intersect(make_ray({0.3, 2, 0.4}, {0, -1, 0}), RayKind::Camera);
    ASSERT_TRUE(above);
    EXPECT_FLOAT_EQ(above->t, 2);
    expect_near(above->geometric_normal, {0, 1, 0}, 0, "normal");
    // u along +x, v along −z, one unit per uv_scale = 2 m.
    EXPECT_NEAR(above->uv[0], 0.15, 1e-7);
    EXPECT_NEAR(above->uv[1], -0.2, 1e-7);
    expect_near(above->dpdu, {2, 0, 0}, 1e-7, "dpdu");
    expect_near(above->dpdv, {0, 0, -2}, 1e-7, "dpdv");
    const auto below = scene->intersect(make_ray({0.3, -3, 0.4}, {0, 2, 0}), RayKind::Camera);  // unnormalised
    ASSERT_TRUE(below);
    EXPECT_FLOAT_EQ(below->t, 1.5f);
    expect_near(below->geometric_normal, {0, 1, 0}, 0, "the front stays the geometric normal");
    EXPECT_TRUE(scene->occluded(make_ray({0, 1, 0}, {0.2, -1, 0})));
}

TEST(PlaneShape, GrazingAndReceedingRaysMissAndFarHitsAreFound) {
    const auto scene = scene_of(plane({0, 0.5, 0}));
    EXPECT_FALSE(scene->intersect(make_ray({-5, 0.5, 0}, {1, 0, 0}), RayKind::Camera));  // in the plane
    EXPECT_FALSE(scene->intersect(make_ray({-5, 1, 0}, {1, 0, 1}), RayKind::Camera));    // parallel above
    EXPECT_FALSE(scene->intersect(make_ray({0, 1, 0}, {0, 1, 0}), RayKind::Camera));     // going away
    EXPECT_FALSE(scene->intersect(make_ray({0, 1, 0}, {0, -1, 0}, 0, 0.4f), RayKind::Camera));  // beyond t_far
    EXPECT_FALSE(scene->occluded(make_ray({-5, 0.5, 0}, {1, 0, 0})));
    // A ray one micro-radian below the horizon meets the plane half a million metres away.
    const auto far = scene->intersect(make_ray({0, 1, 0}, {1, -1e-6, 0}), RayKind::Camera);
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->t, 0.5e6, 1);
    expect_near(far->geometric_normal, {0, 1, 0}, 1e-6, "far normal");
}

TEST(PlaneShape, RandomRaysAgreeWithTheClosedFormToTheIntersectionPrecision) {
    const Vec3d point(0.3, -0.7, 1.1), normal = normalize(Vec3d(0.4, 1, -0.3));
    const auto shape = plane(point, normal);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    int hits = 0;
    for (int i = 0; i < 10000; ++i) {
        const Vec3d o(unit(random) * 4, unit(random) * 4, unit(random) * 4), d(unit(random), unit(random), unit(random));
        const long double approach = (long double)normal.x * d.x + (long double)normal.y * d.y + (long double)normal.z * d.z;
        const long double gap = (long double)normal.x * (point.x - o.x) + (long double)normal.y * (point.y - o.y) +
                                (long double)normal.z * (point.z - o.z);
        const long double expected = gap / approach;
        const std::optional<double> t = shape->first_hit(o, d, 0, INFINITY);
        ASSERT_EQ(t.has_value(), expected > 0) << i;
        if (!t) continue;
        ++hits;
        EXPECT_NEAR(*t, double(expected), 1e-9 * double(expected) + 1e-12) << i;
    }
    EXPECT_GT(hits, 3000);
}

TEST(PlaneShape, AffinePlacementsBakeExactlyAndMirrorsKeepTheHalfSpace) {
    const Transform to_world = Transform::translate({0.5, 1, -0.2}) * Transform::rotate({1, 0.3, 0.2}, 40) *
                               Transform::scale({2, 0.5, 1.5});
    const auto scene = scene_of(plane({0, 0.2, 0}, {0.3, 1, 0}), to_world);
    EXPECT_FALSE(scene->objects()[0].instanced);
    const Vec3d world_point = to_world.point(Vec3d{0, 0.2, 0});
    const Vec3d world_normal = normalize(to_world.normal(normalize(Vec3d(0.3, 1, 0))));
    for (const Vec3d& o : {Vec3d(3, 4, 2), Vec3d(-2, -3, 1)}) {
        const Vec3d d = normalize(world_point + Vec3d(0.3, -0.2, 0.4) - o);
        const auto hit = scene->intersect(make_ray(o, d), RayKind::Camera);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->t, dot(world_normal, world_point - o) / dot(world_normal, d), 1e-5);
        expect_near(hit->geometric_normal, world_normal, 1e-6, "world normal");
    }
    // A mirror across the plane's normal: the half-space behind the plane maps onto the one in front of the image,
    // whose normal therefore points down.
    const auto mirrored = scene_of(plane(), Transform::scale({1, -1, 1}));
    const auto hit = mirrored->intersect(make_ray({0, 1, 0}, {0, -1, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    expect_near(hit->geometric_normal, {0, -1, 0}, 0, "mirrored normal");
}

TEST(PlaneShape, InsideSpansAreTheHalfSpaceBehindThePlane) {
    const auto shape = plane({0, 1, 0});
    QueryScratch scratch;
    std::vector<InsideSpan> spans;
    shape->inside_spans({0, 3, 0}, {0, -1, 0}, 0, 10, spans, scratch);  // entering at t = 2
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_DOUBLE_EQ(spans[0].enter.t, 2);
    EXPECT_TRUE(spans[0].enter.on_surface());
    expect_near(Vec3f(spans[0].enter.normal), {0, 1, 0}, 0, "outward normal");
    EXPECT_DOUBLE_EQ(spans[0].exit.t, 10);
    EXPECT_FALSE(spans[0].exit.on_surface());
    spans.clear();
    shape->inside_spans({0, -1, 0}, {0, 0.5, 0}, 1, 10, spans, scratch);  // leaving at t = 4
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_DOUBLE_EQ(spans[0].enter.t, 1);
    EXPECT_FALSE(spans[0].enter.on_surface());
    EXPECT_DOUBLE_EQ(spans[0].exit.t, 4);
    EXPECT_TRUE(spans[0].exit.on_surface());
    spans.clear();
    shape->inside_spans({0, -1, 0}, {0, 0.5, 0}, 5, 10, spans, scratch);  // the crossing before the range
    EXPECT_TRUE(spans.empty());
    shape->inside_spans({0, 0.5, 0}, {1, 0, 0}, -2, 3, spans, scratch);  // parallel, behind: inside throughout
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_DOUBLE_EQ(spans[0].enter.t, -2);
    EXPECT_DOUBLE_EQ(spans[0].exit.t, 3);
    spans.clear();
    shape->inside_spans({0, 1.5, 0}, {1, 0, 0}, -2, 3, spans, scratch);  // parallel, in front
    shape->inside_spans({0, 1, 0}, {1, 0, 0}, -2, 3, spans, scratch);    // in the plane: on the boundary
    EXPECT_TRUE(spans.empty());
}

TEST(PlaneShape, CutsASphereInACsgIntersection) {
    // The lower half of a unit sphere: rays from above meet the cut face at y = 0 inside the sphere, and the
    // sphere's own surface outside it.
    std::vector<Sphere> ball{{{0, 0, 0}, 1}};
    const auto scene = scene_of(csg_test::csg(CsgOperation::Intersection, csg_test::child(std::make_unique<SphereShape>(ball)),
                                              csg_test::child(plane())));
    const auto cut = scene->intersect(make_ray({0.3, 5, 0.2}, {0, -1, 0}), RayKind::Camera);
    ASSERT_TRUE(cut);
    EXPECT_NEAR(cut->t, 5, 1e-6);
    expect_near(cut->geometric_normal, {0, 1, 0}, 1e-6, "cut face");
    const auto side = scene->intersect(make_ray({5, -0.5, 0}, {-1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->t, 5 - std::sqrt(0.75), 1e-6);
    EXPECT_FALSE(scene->intersect(make_ray({5, 0.5, 0}, {-1, 0, 0}), RayKind::Camera));  // the removed half
    const Bounds3f bounds = scene->objects()[0].shape->bounds();  // narrowed to the sphere's lower half
    EXPECT_FLOAT_EQ(bounds.upper.y, 0);
    EXPECT_FLOAT_EQ(bounds.lower.y, -1);
}

TEST(PlaneShape, SignedDistanceField) {
    const auto shape = plane({0, 1, 0}, {0, 2, 0});
    const auto field = shape->implicit_field();
    EXPECT_DOUBLE_EQ(field->value({3, 4, -2}), 3);
    EXPECT_DOUBLE_EQ(field->value({3, -1, -2}), -2);
    expect_near(Vec3f(field->gradient({1, 1, 1})), {0, 1, 0}, 0, "gradient");
    const Interval range = field->value_range({{-1, 1}, {0.5, 3}, {-1, 1}});
    EXPECT_DOUBLE_EQ(range.lo, -0.5);
    EXPECT_DOUBLE_EQ(range.hi, 2);
    EXPECT_DOUBLE_EQ(field->slope_range({{0, 1}, {0, 1}, {0, 1}}, {0.6, 0.8, 0}).lo, 0.8);
    EXPECT_TRUE(field->may_reach_surface({0, 1.5, 0}, 0.6));
    EXPECT_FALSE(field->may_reach_surface({0, 1.5, 0}, 0.4));
}

TEST(PlaneShape, BoundsReachTheWorldsEdgeAndStayOutOfTheScenesExtent) {
    const Bounds3f flat = plane({0, 0.5, 0})->bounds();  // the half-space below y = 0.5
    EXPECT_FLOAT_EQ(flat.lower.y, float(-kWorldLimit));
    EXPECT_FLOAT_EQ(flat.upper.y, 0.5f);
    EXPECT_FLOAT_EQ(flat.lower.x, float(-kWorldLimit));
    EXPECT_FLOAT_EQ(flat.upper.z, float(kWorldLimit));
    const Bounds3f tilted = plane({0, 0, 0}, {1, 1, 0})->bounds();  // x + y ≤ 0 within the cube
    EXPECT_FLOAT_EQ(tilted.upper.y, float(kWorldLimit));
    EXPECT_FLOAT_EQ(plane({0, 0, 0}, {1, 4, 0})->bounds().upper.y, float(0.25 * kWorldLimit));
    EXPECT_TRUE(plane({0, -3e18, 0})->bounds().empty());  // wholly beyond the world
    EXPECT_TRUE(plane()->is_unbounded());

    auto scene = std::make_unique<RenderScene>();
    SceneObject floor, ball;
    floor.shape = plane();
    ball.shape = std::make_unique<SphereShape>(std::vector<Sphere>{{{0, 1, 0}, 1}});
    scene->add_object(std::move(floor));
    scene->add_object(std::move(ball));
    scene->commit();
    EXPECT_NEAR(scene->bounds().bounding_radius(), std::sqrt(3.0), 1e-5);  // the sphere's box only
    const auto alone = scene_of(plane());
    EXPECT_NEAR(alone->bounds().bounding_radius(), std::sqrt(3.0), 1e-5);  // a metre around the origin
}

TEST(PlaneShapeScene, LoadsAndRejectsBadParameters) {
    mesh_test::ScratchDirectory dir;
    // A transform that moves the plane's reference box far beyond the world is still fine: it is clipped.
    const auto loaded = load_scene(dir.write("plane.json", flat_test::scene_with(R"({"type": "plane", "point": [0, -1, 0], "normal": [0, 0, 1]})",
                                                                       R"("transform": {"rotate": {"axis": [1, 1, 0], "angle": 30}}, )")));
    const Vec3d n = normalize(Transform::rotate({1, 1, 0}, 30).normal(Vec3d(0, 0, 1)));
    const auto hit = loaded->scene->intersect(make_ray(n * 3.0, -n), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3, 1e-5);
    flat_test::expect_errors(dir, {{R"({"type": "plane", "normal": [0, 0, 0]})", "objects[0].shape.normal: the direction must be a finite, non-zero vector"},
                             {R"({"type": "plane", "uv_scale": 0})", "objects[0].shape.uv_scale"},
                             {R"({"type": "plane", "point": [0, 2e18, 0]})", "objects[0].shape.point: the point lies beyond 1e18"},
                             {R"({"type": "plane", "centre": [0, 0, 0]})", "centre"}});
}

}  // namespace
}  // namespace isotrace
