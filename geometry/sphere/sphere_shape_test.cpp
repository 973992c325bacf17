// Analytic sphere through a real RenderScene: hit distances and normals against closed forms, segment limits,
// occlusion, the cancellation-free discriminant, baked similarities, instanced non-uniform scales, counters,
// and the scene-format errors of the "sphere" plugin.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "geometry/csg/csg_test_support.h"
#include "geometry/mesh/mesh_test_support.h"
#include "geometry/sphere/sphere_intersection.h"
#include "geometry/sphere/sphere_shape.h"
#include "renderer/core/render_counters.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

// The nearest root of |o + t d - c| = r strictly inside (t_near, t_far), in long double with the classic
// formula (fine for well-conditioned random rays, which is all it is used for).
std::optional<double> reference_hit(const Vec3d& o, const Vec3d& d, const Vec3d& c, double r, double t_near = 0,
                                    double t_far = INFINITY) {
    const long double fx = (long double)o.x - c.x, fy = (long double)o.y - c.y, fz = (long double)o.z - c.z;
    const long double a = (long double)d.x * d.x + (long double)d.y * d.y + (long double)d.z * d.z;
    const long double b = fx * d.x + fy * d.y + fz * d.z;
    const long double cc = fx * fx + fy * fy + fz * fz - (long double)r * r;
    const long double disc = b * b - a * cc;
    if (disc < 0) return std::nullopt;
    const long double root = std::sqrt(disc);
    const long double t0 = (-b - root) / a, t1 = (-b + root) / a;
    if (t0 > t_near && t0 < t_far) return double(t0);
    if (t1 > t_near && t1 < t_far) return double(t1);
    return std::nullopt;
}

// Distance from c to the line o + t d, relative to r.
double relative_line_distance(const Vec3d& o, const Vec3d& d, const Vec3d& c, double r) {
    const Vec3d f = c - o;
    const Vec3d along = d * (dot(f, d) / dot(d, d));
    return length(f - along) / r;
}

std::unique_ptr<RenderScene> sphere_scene(std::vector<Sphere> spheres, const Transform& to_world = {}) {
    auto scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.name = "spheres";
    object.shape = std::make_unique<SphereShape>(std::move(spheres));
    object.to_world = to_world;
    scene->add_object(std::move(object));
    scene->commit();
    return scene;
}

using csg_test::make_ray;
using csg_test::expect_near;

TEST(SphereShape, RandomRaysHitAtTheClosedFormDistanceWithRadialNormals) {
    const Vec3d centre(0.75, -1.25, 2.5);
    const double radius = 1.5;
    const auto scene = sphere_scene({{centre, radius}});
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-6, 6), unit(-1, 1), scale(0.25, 4);
    int hits = 0, misses = 0;
    for (int i = 0; i < 4000; ++i) {
        // Float-exact ray: the reference uses exactly the origin and direction the renderer sees.
        const Vec3d o(Vec3f(Vec3d{coordinate(random), coordinate(random), coordinate(random)}));
        const Vec3d towards = centre + Vec3d{unit(random), unit(random), unit(random)} * (1.6 * radius);
        const Vec3d d(Vec3f((towards - o) * scale(random) / length(towards - o)));  // not unit length
        const double relative = relative_line_distance(o, d, centre, radius);
        if (std::abs(relative - 1) < 1e-3) continue;  // grazing rays have their own test
        const auto expected = reference_hit(o, d, centre, radius);
        const auto hit = scene->intersect(make_ray(o, d), RayKind::Camera);
        ASSERT_EQ(hit.has_value(), expected.has_value()) << "ray " << i;
        EXPECT_EQ(scene->occluded(make_ray(o, d)), expected.has_value()) << "ray " << i;
        if (!expected) {
            ++misses;
            continue;
        }
        ++hits;
        EXPECT_NEAR(hit->t, *expected, 1e-5 * *expected) << "ray " << i;
        const Vec3d p = o + d * *expected;
        const Vec3d n = (p - centre) / radius;
        expect_near(hit->geometric_normal, n, 1e-5, "geometric normal, ray " + std::to_string(i));
        expect_near(hit->shading_normal, n, 1e-5, "shading normal, ray " + std::to_string(i));
        expect_near(hit->position, p, 1e-5 * (1 + length(p)), "position, ray " + std::to_string(i));
        EXPECT_LE(hit->position_error, 1e-3f);
        EXPECT_EQ(hit->object_index, 0u);
        EXPECT_EQ(hit->primitive_id, 0u);
    }
    EXPECT_GT(hits, 1000);  // the sample really exercises both outcomes
    EXPECT_GT(misses, 500);
}

TEST(SphereShape, SeveralSpheresReportTheNearestAndItsPrimitiveId) {
    const auto scene = sphere_scene({{{0, 0, 10}, 1}, {{0, 0, 5}, 1}, {{0, 0, 20}, 3}});
    const auto hit = scene->intersect(make_ray({0, 0, 0}, {0, 0, 1}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4.0f);
    EXPECT_EQ(hit->primitive_id, 1u);
    const auto beyond = scene->intersect(make_ray({0, 0, 0}, {0, 0, 1}, 12.0f), RayKind::Camera);
    ASSERT_TRUE(beyond);
    EXPECT_FLOAT_EQ(beyond->t, 17.0f);
    EXPECT_EQ(beyond->primitive_id, 2u);
}

TEST(SphereShape, GrazingRaysHitJustInsideAndMissJustOutside) {
    const Vec3d centre(0.3, 0.2, -0.1);
    const double radius = 2;
    const auto scene = sphere_scene({{centre, radius}});
    for (double offset : {1 - 1e-4, 1 - 1e-5, 1 + 1e-5, 1 + 1e-4}) {
        for (int axis = 0; axis < 3; ++axis) {
            Vec3d lateral(0, 0, 0);
            lateral[axis] = radius * offset;
            Vec3d d(0, 0, 0);
            d[(axis + 1) % 3] = 1;
            const Vec3d o = centre + lateral - d * 10.0;
            const Vec3d of{Vec3f(o)};  // what the renderer traces
            const auto expected = reference_hit(of, d, centre, radius);
            const auto hit = scene->intersect(make_ray(o, d), RayKind::Camera);
            ASSERT_EQ(hit.has_value(), offset < 1) << "offset " << offset << " axis " << axis;
            EXPECT_EQ(scene->occluded(make_ray(o, d)), offset < 1);
            if (!hit) continue;
            ASSERT_TRUE(expected);
            EXPECT_NEAR(hit->t, *expected, 1e-5 * *expected);
            // Near tangency the normal is almost the lateral direction.
            EXPECT_NEAR(hit->geometric_normal[axis], 1.0, 1e-2);
            EXPECT_NEAR(length(hit->geometric_normal), 1.0, 1e-6);
        }
    }
}

TEST(SphereShape, RayStartingInsideReportsTheExitWithTheOutwardNormal) {
    const Vec3d centre(1, 2, 3);
    const double radius = 2.5;
    const auto scene = sphere_scene({{centre, radius}});
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int i = 0; i < 500; ++i) {
        const Vec3d o(Vec3f(centre + Vec3d{unit(random), unit(random), unit(random)} * (0.5 * radius)));
        const Vec3d d(Vec3f(Vec3d{unit(random), unit(random), unit(random)}));
        if (length(d) < 0.1) continue;
        const auto expected = reference_hit(o, d, centre, radius);
        ASSERT_TRUE(expected);
        const auto hit = scene->intersect(make_ray(o, d), RayKind::Camera);
        ASSERT_TRUE(hit) << "ray " << i;
        EXPECT_NEAR(hit->t, *expected, 1e-5 * *expected);
        const Vec3d n = (o + d * *expected - centre) / radius;
        expect_near(hit->geometric_normal, n, 1e-5, "exit normal");
        EXPECT_GT(dot(hit->geometric_normal, Vec3f(d)), 0.0f) << "the normal stays outward on the exit";
    }
    // From the centre: exactly the radius along a unit direction.
    const auto from_centre = scene->intersect(make_ray(centre, {0, 1, 0}), RayKind::Camera);
    ASSERT_TRUE(from_centre);
    EXPECT_FLOAT_EQ(from_centre->t, 2.5f);
    expect_near(from_centre->geometric_normal, {0, 1, 0}, 1e-6, "normal from the centre");
}

TEST(SphereShape, OnlyRootsInsideTheSegmentAreReported) {
    // Unit sphere at z = 5 along +z from the origin: roots at t = 4 and t = 6.
    const auto scene = sphere_scene({{{0, 0, 5}, 1}});
    struct Case {
        float t_near, t_far;
        std::optional<float> t;
    };
    const Case cases[] = {
        {0, INFINITY, 4.0f}, {0, 3.9f, std::nullopt}, {4.5f, INFINITY, 6.0f}, {4.5f, 5.5f, std::nullopt},
        {6.5f, INFINITY, std::nullopt}, {3.5f, 4.5f, 4.0f}, {5.5f, 6.5f, 6.0f}, {0, 4.0f, std::nullopt},
        {4.0f, INFINITY, 6.0f},  // roots on the segment's ends are not inside it
    };
    for (const Case& c : cases) {
        const Ray ray = make_ray({0, 0, 0}, {0, 0, 1}, c.t_near, c.t_far);
        const auto hit = scene->intersect(ray, RayKind::Camera);
        ASSERT_EQ(hit.has_value(), c.t.has_value()) << "segment (" << c.t_near << ", " << c.t_far << ")";
        EXPECT_EQ(scene->occluded(ray), c.t.has_value()) << "segment (" << c.t_near << ", " << c.t_far << ")";
        if (hit) {
            EXPECT_FLOAT_EQ(hit->t, *c.t);
        }
    }
    // A direction of length 2 halves the parameter.
    const auto scaled = scene->intersect(make_ray({0, 0, 0}, {0, 0, 2}, 2.5f), RayKind::Camera);
    ASSERT_TRUE(scaled);
    EXPECT_FLOAT_EQ(scaled->t, 3.0f);
}

TEST(SphereShape, OcclusionIsBlockedOnlyByGeometryOnTheSegment) {
    const auto scene = sphere_scene({{{0, 0, 0}, 1}, {{10, 0, 0}, 0.5}});
    EXPECT_TRUE(scene->occluded(make_ray({-5, 0, 0}, {1, 0, 0})));
    EXPECT_FALSE(scene->occluded(make_ray({-5, 2, 0}, {1, 0, 0})));
    EXPECT_FALSE(scene->occluded(make_ray({-5, 0, 0}, {1, 0, 0}, 0, 3.9f)));    // stops before the sphere
    EXPECT_FALSE(scene->occluded(make_ray({-5, 0, 0}, {-1, 0, 0})));           // points away
    EXPECT_TRUE(scene->occluded(make_ray({5, 0, 0}, {1, 0, 0})));              // second sphere
    EXPECT_FALSE(scene->occluded(make_ray({5, 0, 0}, {1, 0, 0}, 0, 4.4f)));
    EXPECT_TRUE(scene->occluded(make_ray({0, 0, 0}, {0, 0, 1})));              // from inside
}

// A sphere of radius 1e-4 at distance 1e4: the classic discriminant b^2 - ac loses every digit here
// (b^2 ~ 1e8, b^2 - ac ~ 1e-8 * (1 - h^2/r^2)), the line-distance form keeps them.
TEST(SphereIntersection, TinySphereFarAwayKeepsItsPrecision) {
    const Vec3d origin(0.125, -0.25, 0.5);
    const Vec3d d = normalize(Vec3d(1, 2, 3));
    Vec3d side = normalize(cross(d, Vec3d(0, 0, 1)));
    const double distance = 1e4, radius = 1e-4;
    for (double h_over_r : {0.0, 0.5, 0.9, 0.99, 0.999}) {
        const double h = h_over_r * radius;
        const Vec3d centre = origin + d * distance + side * h;
        const auto roots = intersect_sphere(origin, d, centre, radius);
        ASSERT_TRUE(roots) << h_over_r;
        const double half_chord = radius * std::sqrt(1 - h_over_r * h_over_r);
        // |centre - exact centre| ~ 1e-12 after rounding, so the chord is known to ~1e-8 of the radius.
        EXPECT_NEAR(roots->t0, distance - half_chord, 1e-3 * radius) << h_over_r;
        EXPECT_NEAR(roots->t1, distance + half_chord, 1e-3 * radius) << h_over_r;
        EXPECT_NEAR(roots->t1 - roots->t0, 2 * half_chord, 1e-3 * half_chord + 1e-9 * radius) << h_over_r;
        // Scaled direction: same points, parameters divided by the scale.
        const auto scaled = intersect_sphere(origin, d * 3.0, centre, radius);
        ASSERT_TRUE(scaled);
        EXPECT_NEAR(scaled->t0 * 3, distance - half_chord, 1e-3 * radius);
    }
    for (double h_over_r : {1.001, 1.01, 2.0}) {
        const Vec3d centre = origin + d * distance + side * (h_over_r * radius);
        EXPECT_FALSE(intersect_sphere(origin, d, centre, radius)) << h_over_r;
    }
    // The test can tell: the textbook discriminant gets the chord wrong by far more than the tolerance.
    {
        const double h_over_r = 0.999;
        const Vec3d centre = origin + d * distance + side * (h_over_r * radius);
        const Vec3d f = origin - centre;
        const double b = dot(f, d), c = dot(f, f) - radius * radius;
        const double naive = b * b - c;  // a = 1
        const double exact = radius * radius * (1 - h_over_r * h_over_r);
        EXPECT_GT(std::abs(naive - exact), 1e-2 * exact);
    }
}

TEST(SphereIntersection, RootsAreOrderedAndSolveTheEquation) {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int i = 0; i < 1000; ++i) {
        const Vec3d o{unit(random) * 4, unit(random) * 4, unit(random) * 4};
        const Vec3d d{unit(random), unit(random), unit(random)};
        const Vec3d c{unit(random), unit(random), unit(random)};
        const double r = 0.5 + std::abs(unit(random));
        const auto roots = intersect_sphere(o, d, c, r);
        const double rel = relative_line_distance(o, d, c, r);
        if (std::abs(rel - 1) < 1e-9) continue;
        ASSERT_EQ(roots.has_value(), rel < 1);
        if (!roots) continue;
        EXPECT_LE(roots->t0, roots->t1);
        for (double t : {roots->t0, roots->t1}) EXPECT_NEAR(length(o + d * t - c), r, 1e-12 * (1 + length(o)));
    }
}

TEST(SphereShape, SimilarityTransformsAreBakedIntoCentreAndRadius) {
    const Transform to_world =
        Transform::translate({1, -2, 3}) * Transform::rotate({1, 1, 0}, 30) * Transform::scale({2.5, 2.5, 2.5});
    auto scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::make_unique<SphereShape>(std::vector<Sphere>{{{0.4, 0, 0}, 1}, {{0, 5, 0}, 0.5}});
    object.to_world = to_world;
    scene->add_object(std::move(object));
    scene->commit();
    const SceneObject& committed = scene->objects()[0];
    EXPECT_FALSE(committed.instanced);
    EXPECT_EQ(scene->build_statistics().instanced_objects, 0u);
    const auto& baked = static_cast<const SphereShape&>(*committed.shape).spheres();
    ASSERT_EQ(baked.size(), 2u);
    const Vec3d c0 = to_world.point(Vec3d(0.4, 0, 0)), c1 = to_world.point(Vec3d(0, 5, 0));
    EXPECT_NEAR(length(baked[0].centre - c0), 0, 1e-12);
    EXPECT_NEAR(length(baked[1].centre - c1), 0, 1e-12);
    EXPECT_NEAR(baked[0].radius, 2.5, 1e-12);
    EXPECT_NEAR(baked[1].radius, 1.25, 1e-12);

    const Vec3d o(-10, 0.5, 0.25);
    const Vec3d d(Vec3f(normalize(c0 - o)));
    const auto hit = scene->intersect(make_ray(o, d), RayKind::Camera);
    ASSERT_TRUE(hit);
    const auto expected = reference_hit(Vec3d(Vec3f(o)), d, c0, 2.5);
    ASSERT_TRUE(expected);
    EXPECT_NEAR(hit->t, *expected, 1e-5 * *expected);
    expect_near(hit->geometric_normal, (Vec3d(Vec3f(o)) + d * *expected - c0) / 2.5, 1e-5, "baked normal");
}

TEST(SphereShape, MirroringSimilarityIsBakedAndNormalsStayOutward) {
    const Transform mirror = Transform::translate({0, 0, 4}) * Transform::scale({-2, 2, 2});
    auto scene = sphere_scene({{{1, 0, 0}, 1}}, mirror);
    EXPECT_FALSE(scene->objects()[0].instanced);
    // Centre (-2, 0, 4), radius 2.
    const auto hit = scene->intersect(make_ray({-2, 0, 0}, {0, 0, 1}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2.0f);
    expect_near(hit->geometric_normal, {0, 0, -1}, 1e-6, "mirrored normal");
}

TEST(SphereShape, NonUniformScaleIsInstancedAndHitsTheEllipsoidExactly) {
    // Unit sphere -> ellipsoid with semi-axes (1, 2, 3) rotated about z and moved.
    const Transform to_world =
        Transform::translate({0.5, -1, 2}) * Transform::rotate({0, 0, 1}, 35) * Transform::scale({1, 2, 3});
    const auto scene = sphere_scene({{{0, 0, 0}, 1}}, to_world);
    ASSERT_TRUE(scene->objects()[0].instanced);
    EXPECT_EQ(scene->build_statistics().instanced_objects, 1u);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3d o(Vec3f(Vec3d{unit(random), unit(random), unit(random)} * 8.0));
        const Vec3d target = to_world.point(Vec3d{unit(random), unit(random), unit(random)} * 0.8);
        const Vec3d d(Vec3f(target - o));
        // Object space: the ellipsoid is the unit sphere and t is unchanged by the affine map.
        const Vec3d oo = to_world.inverse().point(o), od = to_world.inverse().vector(d);
        if (std::abs(relative_line_distance(oo, od, {0, 0, 0}, 1) - 1) < 1e-3) continue;
        const auto expected = reference_hit(oo, od, {0, 0, 0}, 1);
        const auto hit = scene->intersect(make_ray(o, d), RayKind::Camera);
        ASSERT_EQ(hit.has_value(), expected.has_value()) << "ray " << i;
        if (!hit) continue;
        ++hits;
        EXPECT_NEAR(hit->t, *expected, 1e-5 * *expected) << "ray " << i;
        // World normal: inverse transpose of the object-space normal (the local point itself).
        const Vec3d n = normalize(to_world.normal(oo + od * *expected));
        expect_near(hit->geometric_normal, n, 1e-5, "ellipsoid normal, ray " + std::to_string(i));
        expect_near(hit->shading_normal, n, 1e-5, "ellipsoid shading normal");
        EXPECT_TRUE(scene->occluded(make_ray(o, d)));
    }
    EXPECT_GT(hits, 400);
    // Along the long axis of the ellipsoid (object z = world z after the rotation about z): semi-axis 3.
    const Vec3d centre = to_world.point(Vec3d(0, 0, 0));
    const auto top = scene->intersect(make_ray(centre + Vec3d(0, 0, 10), {0, 0, -1}), RayKind::Camera);
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->t, 7.0, 1e-5 * 7);
    expect_near(top->geometric_normal, {0, 0, 1}, 1e-5, "pole normal");
}

TEST(SphereShape, UvDerivativesAreThoseOfTheSphericalCoordinates) {
    // The second sphere of the set, so that the hit's primitive picks the radius.
    const Vec3d centre(1, 2, 3);
    const double r = 2;
    const SphereShape shape({{{0, 0, 0}, 0.5}, {centre, r}});
    EXPECT_TRUE(shape.has_uv());
    const auto shade = [&](const Vec3d& normal) {
        RTCHit hit{};
        hit.primID = 1;
        return shape.shading(hit, Vec3f(normal), centre + normal * r);
    };
    // p(u, v) = c + r·(sin θ sin φ, cos θ, sin θ cos φ), φ = 2π(u − ½), θ = πv.
    const auto point = [&](double u, double v) {
        const double phi = 2 * M_PI * (u - 0.5), theta = M_PI * v;
        return centre + Vec3d(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)) * r;
    };
    // Known points: +z (u = v = ½) and +x (u = ¾, v = ½).
    LocalShading s = shade({0, 0, 1});
    expect_near(s.dpdu, {2 * M_PI * r, 0, 0}, 1e-5, "");
    expect_near(s.dpdv, {0, -M_PI * r, 0}, 1e-5, "");
    s = shade({1, 0, 0});
    expect_near(s.dpdu, {0, 0, -2 * M_PI * r}, 1e-5, "");
    expect_near(s.dpdv, {0, -M_PI * r, 0}, 1e-5, "");
    // Random points against central differences of p at the hit's own uv, and tangent to the sphere.
    std::mt19937 random(21);
    std::uniform_real_distribution<double> unit(0, 1);
    const double h = 1e-6;
    for (int i = 0; i < 200; ++i) {
        const double u0 = unit(random), v0 = 0.02 + 0.96 * unit(random);
        const Vec3d normal = normalize(point(u0, v0) - centre);
        s = shade(normal);
        const double u = s.uv[0], v = s.uv[1];
        const Vec3d dpdu = (point(u + h, v) - point(u - h, v)) / (2 * h);
        const Vec3d dpdv = (point(u, v + h) - point(u, v - h)) / (2 * h);
        EXPECT_NEAR(length(Vec3d(s.dpdu) - dpdu), 0, 1e-4 * length(dpdu) + 1e-5) << i;
        EXPECT_NEAR(length(Vec3d(s.dpdv) - dpdv), 0, 1e-4 * length(dpdv)) << i;
        EXPECT_NEAR(dot(Vec3d(s.dpdu), normal), 0, 1e-5 * r) << i;
        EXPECT_NEAR(dot(Vec3d(s.dpdv), normal), 0, 1e-5 * r) << i;
    }
    // At a pole u does not move the point, and v still runs down the meridian.
    s = shade({0, 1, 0});
    EXPECT_EQ(s.dpdu, Vec3f(0, 0, 0));
    expect_near(s.dpdv, {0, 0, M_PI * r}, 1e-5, "");
}

TEST(SphereShape, CountersRecordTestsAndCandidateHits) {
    const auto scene = sphere_scene({{{0, 0, 5}, 1}});
    const auto before = counters::totals();
    const auto get = [](const CounterTotals& totals) {
        const auto found = totals.geometry.find("sphere");
        return found == totals.geometry.end() ? GeometryTypeCounts{} : found->second;
    };
    const GeometryTypeCounts b = get(before);
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, 0}, {0, 0, 1}), RayKind::Camera));
    ASSERT_TRUE(scene->occluded(make_ray({0, 0, 0}, {0, 0, 1})));
    ASSERT_FALSE(scene->intersect(make_ray({0, 0.9, 0}, {0, 0.5, 1}), RayKind::Secondary));  // bounds, no root
    const auto after = counters::totals();
    const GeometryTypeCounts a = get(after);
    EXPECT_TRUE(a.counts_tests);
    EXPECT_GE(a.tests, b.tests + 2);
    EXPECT_GE(a.candidate_hits, b.candidate_hits + 2);
    EXPECT_GE(a.closest_hits, b.closest_hits + 1);
    EXPECT_GE(after.camera_rays, before.camera_rays + 1);
    EXPECT_GE(after.shadow_rays, before.shadow_rays + 1);
    EXPECT_GE(after.secondary_rays, before.secondary_rays + 1);
}

// ---- scene-format errors ----------------------------------------------------------------------------------

std::string scene_with_shape(const std::string& shape) {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", "shape": )" +
           shape + "}]}";
}

TEST(SphereShapeScene, LoadsSingleAndListForms) {
    mesh_test::ScratchDirectory dir;
    {
        const auto loaded = load_scene(dir.write("one.json", scene_with_shape(
                                                                  R"({"type": "sphere", "center": [1, 2, 3], "radius": 0.5})")));
        const auto& spheres = static_cast<const SphereShape&>(*loaded->scene->objects()[0].shape).spheres();
        ASSERT_EQ(spheres.size(), 1u);
        EXPECT_EQ(spheres[0].centre, Vec3d(1, 2, 3));
        EXPECT_EQ(spheres[0].radius, 0.5);
    }
    {
        const auto loaded = load_scene(dir.write(
            "list.json",
            scene_with_shape(R"({"type": "sphere", "spheres": [{"center": [0, 0, 0]}, {"center": [3, 0, 0], "radius": 2}]})")));
        const auto& spheres = static_cast<const SphereShape&>(*loaded->scene->objects()[0].shape).spheres();
        ASSERT_EQ(spheres.size(), 2u);
        EXPECT_EQ(spheres[0].radius, 1.0);
        EXPECT_EQ(spheres[1].centre, Vec3d(3, 0, 0));
        EXPECT_EQ(spheres[1].radius, 2.0);
        const auto hit = loaded->scene->intersect(make_ray({3, 0, 10}, {0, 0, -1}), RayKind::Camera);
        ASSERT_TRUE(hit);
        EXPECT_FLOAT_EQ(hit->t, 8.0f);
        EXPECT_EQ(hit->primitive_id, 1u);
    }
}

TEST(SphereShapeScene, NegativeOrZeroRadiusIsAnInputErrorAtTheRadius) {
    mesh_test::ScratchDirectory dir;
    for (const char* radius : {"-1", "0"}) {
        const std::string path =
            dir.write("s.json", scene_with_shape(std::string(R"({"type": "sphere", "radius": )") + radius + "}"));
        const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find("objects[0].shape.radius"), std::string::npos) << message;
        EXPECT_NE(message.find(path + ":4:"), std::string::npos) << message;
    }
    const std::string in_list = dir.write(
        "l.json", scene_with_shape(R"({"type": "sphere", "spheres": [{"center": [0, 0, 0], "radius": -2}]})"));
    const std::string message = mesh_test::input_error_message([&] { load_scene(in_list); });
    EXPECT_NE(message.find("spheres[0].radius"), std::string::npos) << message;
}

TEST(SphereShapeScene, CenterAndSpheresTogetherIsAnInputError) {
    mesh_test::ScratchDirectory dir;
    for (const char* shape : {R"({"type": "sphere", "center": [0, 0, 0], "spheres": [{"center": [1, 0, 0]}]})",
                              R"({"type": "sphere", "radius": 2, "spheres": [{"center": [1, 0, 0]}]})"}) {
        const std::string path = dir.write("s.json", scene_with_shape(shape));
        const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find("not both"), std::string::npos) << message;
        EXPECT_NE(message.find("objects[0].shape"), std::string::npos) << message;
    }
}

TEST(SphereShapeScene, EmptySpheresListIsAnInputError) {
    mesh_test::ScratchDirectory dir;
    for (const char* shape : {R"({"type": "sphere", "spheres": []})",
                              R"({"type": "sphere", "center": [0, 0, 0], "spheres": []})"}) {
        const std::string path = dir.write("s.json", scene_with_shape(shape));
        const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find("objects[0].shape.spheres"), std::string::npos) << message;
        EXPECT_NE(message.find("empty"), std::string::npos) << message;
    }
}

TEST(SphereShapeScene, UnknownKeysInsideTheListAreRejected) {
    mesh_test::ScratchDirectory dir;
    const std::string path =
        dir.write("s.json", scene_with_shape(R"({"type": "sphere", "spheres": [{"centre": [0, 0, 0]}]})"));
    const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
    EXPECT_NE(message.find("centre"), std::string::npos) << message;
}

TEST(SphereShape, CertainlyOutsideOnlyBeyondTheGivenDistance) {
    const SphereShape spheres({{{0, 0, 0}, 1}, {{3, 0, 0}, 0.5}});
    EXPECT_TRUE(spheres.certainly_outside({0, 1.5, 0}, 0.49));   // 0.5 from the first, 1.58 from the second
    EXPECT_FALSE(spheres.certainly_outside({0, 1.5, 0}, 0.51));
    EXPECT_FALSE(spheres.certainly_outside({3, 0.9, 0}, 0.41));  // the second is 0.4 away
    EXPECT_FALSE(spheres.certainly_outside({0.2, 0, 0}, 0));     // inside
    EXPECT_FALSE(spheres.certainly_outside({1, 0, 0}, 0));       // on the surface
}

}  // namespace
}  // namespace isotrace
