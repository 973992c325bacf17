// CSG shapes through a real RenderScene: set identities on random rays, two spheres against an oracle that
// classifies points, the spherical shell's hit sequence and flipped normals, shadow rays, touching and
// coincident solids, nesting, children under transforms they cannot bake, parts, and the counters.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "geometry/csg/csg_test_support.h"
#include "geometry/sphere/sphere_intersection.h"
#include "renderer/core/render_counters.h"

namespace isotrace {
namespace {

using namespace csg_test;

struct RandomRay {
    Vec3d origin, direction;
};

// Rays from a shell of radius 4..6 around the origin towards points in the unit-ish ball: most hit the solids.
std::vector<RandomRay> random_rays(int count, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1), distance(4, 6);
    std::vector<RandomRay> rays;
    while (int(rays.size()) < count) {
        const Vec3d from{unit(random), unit(random), unit(random)};
        if (length(from) < 0.1 || length(from) > 1) continue;
        const Vec3d origin = normalize(from) * distance(random);
        const Vec3d target{unit(random) * 1.5, unit(random) * 1.5, unit(random) * 1.5};
        rays.push_back({Vec3d(Vec3f(origin)), Vec3d(Vec3f(target - origin))});
    }
    return rays;
}

// Both scenes give the same nearest hits (distance and normal) along random rays; returns how many hit.
int expect_same_hits(const RenderScene& actual, const RenderScene& expected, unsigned seed) {
    int hits = 0;
    for (const RandomRay& r : random_rays(2000, seed)) {
        const Ray ray = make_ray(r.origin, r.direction);
        const auto hit = actual.intersect(ray, RayKind::Camera), reference = expected.intersect(ray, RayKind::Camera);
        EXPECT_EQ(hit.has_value(), reference.has_value());
        if (!hit || !reference) continue;
        ++hits;
        EXPECT_NEAR(hit->t, reference->t, 1e-5 * reference->t);
        expect_near(hit->geometric_normal, Vec3d(reference->geometric_normal), 1e-4, "normal");
    }
    return hits;
}

std::unique_ptr<Shape> sphere_a() { return sphere({0.25, 0, 0}, 1); }
std::unique_ptr<Shape> sphere_b() { return sphere({-0.5, 0.3, 0.1}, 0.8); }

TEST(CsgShape, AMinusAIsEmptyAndAUnionAOrAIntersectionAIsA) {
    const auto plain = scene_of(sphere_a());
    const auto minus = scene_of(csg(CsgOperation::Difference, child(sphere_a()), child(sphere_a())));
    const auto with_box_minus = scene_of(csg(CsgOperation::Difference, child(box({0, 0, 0}, {1, 0.5, 0.75})),
                                             child(box({0, 0, 0}, {1, 0.5, 0.75}))));
    const auto union_self = scene_of(csg(CsgOperation::Union, child(sphere_a()), child(sphere_a())));
    const auto meet_self = scene_of(csg(CsgOperation::Intersection, child(sphere_a()), child(sphere_a())));
    int hits = 0;
    for (const RandomRay& r : random_rays(2000, 11)) {
        const Ray ray = make_ray(r.origin, r.direction);
        EXPECT_FALSE(minus->intersect(ray, RayKind::Camera));
        EXPECT_FALSE(minus->occluded(ray));
        EXPECT_FALSE(with_box_minus->intersect(ray, RayKind::Camera));
        const auto expected = plain->intersect(ray, RayKind::Camera);
        for (const RenderScene* same : {union_self.get(), meet_self.get()}) {
            const auto hit = same->intersect(ray, RayKind::Camera);
            ASSERT_EQ(hit.has_value(), expected.has_value());
            if (!hit) continue;
            EXPECT_FLOAT_EQ(hit->t, expected->t);
            expect_near(hit->geometric_normal, Vec3d(expected->geometric_normal), 1e-6, "same normal as A");
        }
        hits += expected.has_value();
    }
    EXPECT_GT(hits, 500);
}

TEST(CsgShape, UnionMinusBLiesInA) {
    const auto scene = scene_of(csg(CsgOperation::Difference,
                                    child(csg(CsgOperation::Union, child(sphere_a()), child(sphere_b()))),
                                    child(sphere_b())));
    int hits = 0;
    for (const RandomRay& r : random_rays(2000, 12)) {
        const auto hit = scene->intersect(make_ray(r.origin, r.direction), RayKind::Camera);
        if (!hit) continue;
        ++hits;
        EXPECT_LE(length(Vec3d(hit->position) - Vec3d(0.25, 0, 0)), 1 + 1e-5) << "hit outside A";
    }
    EXPECT_GT(hits, 300);
}

// Two overlapping spheres under each operator against the point-classifying oracle, over random rays and random
// segment starts (so that some rays start inside either sphere, or inside the result).
TEST(CsgShape, TwoSpheresMatchTheClosedFormUnderEveryOperator) {
    const Vec3d ca(0.25, 0, 0), cb(-0.5, 0.3, 0.1);
    const double ra = 1, rb = 0.8;
    const Membership a = in_sphere(ca, ra), b = in_sphere(cb, rb);
    struct Case {
        CsgOperation operation;
        Membership inside;
        const char* name;
    };
    const Case cases[] = {
        {CsgOperation::Union, [&](const Vec3d& p) { return a(p) || b(p); }, "union"},
        {CsgOperation::Intersection, [&](const Vec3d& p) { return a(p) && b(p); }, "intersection"},
        {CsgOperation::Difference, [&](const Vec3d& p) { return a(p) && !b(p); }, "difference"},
    };
    std::mt19937 random(13);
    std::uniform_real_distribution<double> start(0, 6);
    for (const Case& c : cases) {
        const auto scene = scene_of(csg(c.operation, child(sphere(ca, ra)), child(sphere(cb, rb))));
        int hits = 0;
        for (const RandomRay& r : random_rays(1500, 14)) {
            std::vector<double> candidates;
            bool near_tangent = false;
            for (const auto& [centre, radius] : {std::pair{ca, ra}, std::pair{cb, rb}}) {
                const Vec3d to_line = (r.origin - centre) - r.direction * (dot(r.origin - centre, r.direction) /
                                                                          dot(r.direction, r.direction));
                near_tangent |= std::abs(length(to_line) - radius) < 1e-3;
                if (const auto roots = intersect_sphere(r.origin, r.direction, centre, radius)) {
                    candidates.push_back(roots->t0);
                    candidates.push_back(roots->t1);
                }
            }
            if (near_tangent) continue;
            const float t_near = float(start(random) / length(r.direction));
            const auto expected = first_membership_change(r.origin, r.direction, candidates, c.inside, t_near);
            const Ray ray = make_ray(r.origin, r.direction, t_near);
            const auto hit = scene->intersect(ray, RayKind::Camera);
            ASSERT_EQ(hit.has_value(), expected.has_value()) << c.name;
            EXPECT_EQ(scene->occluded(ray), expected.has_value()) << c.name;
            if (!hit) continue;
            ++hits;
            EXPECT_NEAR(hit->t, *expected, 1e-5 * *expected) << c.name;
            // Outward: a step along the normal leaves the result, a step against it enters (away from the
            // circle where the spheres meet, which such steps may cross).
            const Vec3d p = r.origin + r.direction * *expected, n(hit->geometric_normal);
            if (std::abs(length(p - ca) - ra) < 1e-3 && std::abs(length(p - cb) - rb) < 1e-3) continue;
            EXPECT_FALSE(c.inside(p + n * 1e-4)) << c.name;
            EXPECT_TRUE(c.inside(p - n * 1e-4)) << c.name;
        }
        EXPECT_GT(hits, 200) << c.name;
    }
}

TEST(CsgShape, SphericalShellHitSequenceFromOutsideFromTheMaterialAndFromTheHollow) {
    const auto scene = scene_of(csg(CsgOperation::Difference, child(sphere({0, 0, 0}, 2)), child(sphere({0, 0, 0}, 1))));
    const auto from_outside = hit_sequence(*scene, make_ray({-5, 0, 0}, {1, 0, 0}));
    ASSERT_EQ(from_outside.size(), 4u);
    const double expected_t[] = {3, 4, 6, 7};
    // Outward normals of the shell: away from the material, so towards the centre on the inner sphere.
    const Vec3d expected_normal[] = {{-1, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {1, 0, 0}};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(from_outside[i].t, expected_t[i], 1e-5) << "hit " << i;
        expect_near(from_outside[i].geometric_normal, expected_normal[i], 1e-6, "hit " + std::to_string(i));
    }
    const auto from_material = scene->intersect(make_ray({-1.5, 0, 0}, {1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(from_material);
    EXPECT_NEAR(from_material->t, 0.5, 1e-6);
    expect_near(from_material->geometric_normal, {1, 0, 0}, 1e-6, "inner surface from the material");
    const auto from_hollow = scene->intersect(make_ray({0, 0, 0}, {0, 1, 0}), RayKind::Camera);
    ASSERT_TRUE(from_hollow);
    EXPECT_NEAR(from_hollow->t, 1, 1e-6);
    expect_near(from_hollow->geometric_normal, {0, -1, 0}, 1e-6, "inner surface from the hollow");
    EXPECT_TRUE(scene->occluded(make_ray({0, 0, 0}, {0, 1, 0})));
    EXPECT_FALSE(scene->occluded(make_ray({0, 0, 0}, {0, 1, 0}, 0, 0.9f)));
    EXPECT_TRUE(scene->occluded(make_ray({-1.5, 0, 0}, {-1, 0, 0})));  // from the material outwards
}

TEST(CsgShape, ShadowRaysAgreeWithNearestHitsOnRandomSegments) {
    const auto scene = scene_of(csg(CsgOperation::Difference, child(box({0, 0, 0}, {1, 1, 1})),
                                    child(sphere({0.5, 0.5, 0.5}, 0.9)), child(box({-1, 0, 0}, {0.5, 0.25, 2}))));
    std::mt19937 random(15);
    std::uniform_real_distribution<double> fraction(0, 1);
    int blocked = 0;
    for (const RandomRay& r : random_rays(3000, 16)) {
        const float t_near = float(fraction(random) * 0.8), t_far = float(t_near + fraction(random) * 1.2);
        const Ray ray = make_ray(r.origin, r.direction, t_near, t_far);
        const bool hit = scene->intersect(ray, RayKind::Camera).has_value();
        EXPECT_EQ(scene->occluded(ray), hit);
        blocked += hit;
    }
    EXPECT_GT(blocked, 300);
}

TEST(CsgShape, TouchingBoxesOfAUnionMergeAndCoincidentFacesCancel) {
    // Two unit cubes sharing the face x = 1.
    const auto joined = scene_of(csg(CsgOperation::Union, child(box({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5})),
                                     child(box({1.5, 0.5, 0.5}, {0.5, 0.5, 0.5}))));
    const auto through = hit_sequence(*joined, make_ray({-1, 0.3, 0.6}, {1, 0, 0}));
    ASSERT_EQ(through.size(), 2u) << "no surface at the shared face";
    EXPECT_NEAR(through[0].t, 1, 1e-6);
    EXPECT_NEAR(through[1].t, 3, 1e-6);
    const auto from_inside = joined->intersect(make_ray({0.5, 0.3, 0.6}, {1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(from_inside);
    EXPECT_NEAR(from_inside->t, 1.5, 1e-6);
    // A box minus a box that shares its top face: the top face is gone, the cut's floor appears.
    const auto notched = scene_of(csg(CsgOperation::Difference, child(box({0, 0, 0}, {1, 1, 1})),
                                      child(box({0, 0.5, 0}, {0.5, 0.5, 0.5}))));
    const auto down = hit_sequence(*notched, make_ray({0, 3, 0}, {0, -1, 0}));
    ASSERT_EQ(down.size(), 2u);
    EXPECT_NEAR(down[0].t, 3, 1e-6) << "floor of the notch";
    expect_near(down[0].geometric_normal, {0, 1, 0}, 1e-6, "floor normal (flipped bottom face of the notch)");
    EXPECT_NEAR(down[1].t, 4, 1e-6);
    // Boxes that only touch have no common interior.
    const auto touching_meet = scene_of(csg(CsgOperation::Intersection, child(box({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5})),
                                            child(box({1.5, 0.5, 0.5}, {0.5, 0.5, 0.5}))));
    EXPECT_FALSE(touching_meet->intersect(make_ray({-1, 0.3, 0.6}, {1, 0, 0}), RayKind::Camera));
}

// (A ∪ B) − C nested, against the oracle; and parts numbered depth-first through the nesting.
TEST(CsgShape, NestedTreesCombineAndNumberTheirParts) {
    const Vec3d ca(0.25, 0, 0), cb(-0.5, 0.3, 0.1), cc(0, -0.6, 0.2);
    auto shape = csg(CsgOperation::Difference, child(csg(CsgOperation::Union, child(sphere(ca, 1)),
                                                               child(sphere(cb, 0.8)))),
                           child(sphere(cc, 0.7)));
    EXPECT_EQ(shape->part_materials().size(), 3u);
    const auto scene = scene_of(std::move(shape));
    const Membership a = in_sphere(ca, 1), b = in_sphere(cb, 0.8), c = in_sphere(cc, 0.7);
    const Membership inside = [&](const Vec3d& p) { return (a(p) || b(p)) && !c(p); };
    int parts_seen[3] = {0, 0, 0};
    for (const RandomRay& r : random_rays(2000, 17)) {
        std::vector<double> candidates;
        bool near_tangent = false;  // the oracle's steps are too coarse there
        for (const auto& [centre, radius] : {std::pair{ca, 1.0}, std::pair{cb, 0.8}, std::pair{cc, 0.7}})
            if (const auto roots = intersect_sphere(r.origin, r.direction, centre, radius)) {
                near_tangent |= roots->t1 - roots->t0 < 1e-3;
                candidates.push_back(roots->t0);
                candidates.push_back(roots->t1);
            }
        if (near_tangent) continue;
        const auto expected = first_membership_change(r.origin, r.direction, candidates, inside);
        const auto hit = scene->intersect(make_ray(r.origin, r.direction), RayKind::Camera);
        ASSERT_EQ(hit.has_value(), expected.has_value());
        if (!hit) continue;
        EXPECT_NEAR(hit->t, *expected, 1e-5 * *expected);
        // The part is the sphere the hit lies on (depth-first: a, b, c).
        const Vec3d p(hit->position);
        const double off[3] = {std::abs(length(p - ca) - 1), std::abs(length(p - cb) - 0.8),
                               std::abs(length(p - cc) - 0.7)};
        const std::uint32_t part = hit->primitive_id;
        ASSERT_LT(part, 3u);
        EXPECT_LT(off[part], 1e-4) << "part " << part;
        ++parts_seen[part];
    }
    for (int count : parts_seen) EXPECT_GT(count, 20);
}

// A child under a non-uniform scale cannot bake it: it keeps the transform and sees rays mapped into its own space
// (direction not unit). Its hits equal those of the same ellipsoid instanced by the scene, before and after the
// object's own transform is baked into the CSG.
TEST(CsgShape, ChildrenKeepTransformsTheyCannotBakeAndMatchInstancedShapes) {
    const Transform squash = Transform::translate({0.2, 0, 0}) * Transform::rotate({0, 0, 1}, 30) *
                             Transform::scale({1, 0.5, 1.5});
    const Transform to_world = Transform::translate({0.5, -0.25, 0}) * Transform::scale({1.2, 1.2, 1.2});
    auto shape = csg(CsgOperation::Union, child(sphere({0, 0, 0}, 1), squash), child(box({30, 30, 30}, {0.1, 0.1, 0.1})));
    const auto in_csg = scene_of(std::move(shape), to_world);
    EXPECT_FALSE(in_csg->objects()[0].instanced);
    const auto instanced = scene_of(sphere({0, 0, 0}, 1), to_world * squash);
    ASSERT_TRUE(instanced->objects()[0].instanced);
    EXPECT_GT(expect_same_hits(*in_csg, *instanced, 18), 300);
}

// The same CSG placed by a similarity (baked into every child) and given in world coordinates directly.
TEST(CsgShape, BakedObjectTransformEqualsTheTransformedTree) {
    const Transform to_world = Transform::translate({0.3, 0.1, -0.2}) * Transform::rotate({1, 2, 3}, 40) *
                               Transform::scale({0.8, 0.8, 0.8});
    const auto placed = scene_of(csg(CsgOperation::Difference, child(box({0, 0, 0}, {1, 1, 1})),
                                     child(sphere({0.4, 0.4, 0.4}, 0.9))),
                                 to_world);
    const auto world = scene_of(csg(CsgOperation::Difference, child(box({0, 0, 0}, {1, 1, 1}), to_world),
                                    child(sphere(to_world.point(Vec3d(0.4, 0.4, 0.4)), 0.72))));
    EXPECT_GT(expect_same_hits(*placed, *world, 19), 300);
}

// A sphere set is one solid, the union of its spheres: overlapping spheres merge, each end keeps its sphere.
TEST(CsgShape, ASphereListIsTheUnionOfItsSpheres) {
    const SphereShape spheres({{{0, 0, 0}, 1}, {{1.5, 0, 0}, 1}, {{5, 0, 0}, 0.5}});
    std::vector<InsideSpan> spans;
    QueryScratch scratch;
    spheres.inside_spans({-5, 0, 0}, {1, 0, 0}, 0, 100, spans, scratch);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_DOUBLE_EQ(spans[0].enter.t, 4);
    EXPECT_EQ(spans[0].enter.primitive, 0u);
    EXPECT_DOUBLE_EQ(spans[0].exit.t, 7.5);
    EXPECT_EQ(spans[0].exit.primitive, 1u);
    EXPECT_DOUBLE_EQ(spans[1].enter.t, 9.5);
    EXPECT_EQ(spans[1].exit.primitive, 2u);
    const auto scene = scene_of(csg(CsgOperation::Difference, child(box({0, 0, 0}, {10, 0.25, 0.25})),
                                    child(std::make_unique<SphereShape>(spheres))));
    const auto hits = hit_sequence(*scene, make_ray({-15, 0, 0}, {1, 0, 0}));
    // The bar x in [-10, 10] with the merged pair (x in [-1, 2.5]) and the small sphere (x in [4.5, 5.5]) cut out.
    const float expected[] = {5, 14, 17.5, 19.5, 20.5, 25};
    ASSERT_EQ(hits.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(hits[i].t, expected[i], 1e-5) << "hit " << i;
}

TEST(CsgShape, BoundsFollowTheOperator) {
    const auto make = [](CsgOperation operation) {
        return csg(operation, child(box({0, 0, 0}, {1, 1, 1})), child(box({1.5, 0, 0}, {1, 0.5, 0.5})));
    };
    EXPECT_EQ(make(CsgOperation::Union)->bounds().upper, Vec3f(2.5, 1, 1));
    EXPECT_EQ(make(CsgOperation::Union)->bounds().lower, Vec3f(-1, -1, -1));
    EXPECT_EQ(make(CsgOperation::Intersection)->bounds().lower, Vec3f(0.5, -0.5, -0.5));
    EXPECT_EQ(make(CsgOperation::Intersection)->bounds().upper, Vec3f(1, 0.5, 0.5));
    EXPECT_EQ(make(CsgOperation::Difference)->bounds().upper, Vec3f(1, 1, 1));
    // Disjoint operands: empty intersection, a geometry without primitives, nothing to hit.
    auto apart = csg(CsgOperation::Intersection, child(box({0, 0, 0}, {1, 1, 1})), child(box({0, 5, 0}, {1, 1, 1})));
    EXPECT_TRUE(apart->bounds().empty());
    EXPECT_FALSE(scene_of(std::move(apart))->intersect(make_ray({0, 0, -5}, {0, 0, 1}), RayKind::Camera));
}

TEST(CsgShape, CountersRecordTestsHitsAndSpanCombinations) {
    const auto scene = scene_of(csg(CsgOperation::Difference, child(sphere({0, 0, 5}, 1)), child(sphere({0, 0, 4}, 0.5))));
    const auto before = counters::totals();
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, 0}, {0, 0, 1}), RayKind::Camera));
    ASSERT_TRUE(scene->occluded(make_ray({0, 0, 0}, {0, 0, 1})));
    const auto after = counters::totals();
    const GeometryTypeCounts b = before.geometry.count("csg") ? before.geometry.at("csg") : GeometryTypeCounts{};
    const GeometryTypeCounts a = after.geometry.at("csg");
    EXPECT_TRUE(a.counts_tests);
    EXPECT_GE(a.tests, b.tests + 2);
    EXPECT_GE(a.candidate_hits, b.candidate_hits + 2);
    EXPECT_GE(a.closest_hits, b.closest_hits + 1);
    const auto named = [](const CounterTotals& t, const std::string& key) {
        return t.named.count(key) ? t.named.at(key) : 0;
    };
    EXPECT_GE(named(after, "csg.span_combinations"), named(before, "csg.span_combinations") + 2);
    EXPECT_GE(named(after, "csg.span_events"), named(before, "csg.span_events") + 8);
}

}  // namespace
}  // namespace isotrace
