// The "superquadric" shape through Embree and as a Solid: inside spans against closed forms and dense sampling,
// instanced versus baked placements, counters, and the scene plugin's format and errors.
#include "geometry/superquadric/superquadric_shape.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "geometry/csg/csg_shape.h"
#include "geometry/mesh/mesh_test_support.h"
#include "geometry/superquadric/superquadric_test_support.h"
#include "renderer/core/memory_budget.h"
#include "renderer/core/render_counters.h"
#include "renderer/params/json_document.h"
#include "renderer/params/scene_node.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

using superquadric_test::make_superquadric;
using superquadric_test::random_deformations;

std::vector<InsideSpan> spans_of(const SuperquadricShape& shape, const Vec3d& o, const Vec3d& d, double t_min,
                                 double t_max) {
    std::vector<InsideSpan> spans;
    QueryScratch scratch;
    shape.inside_spans(o, d, t_min, t_max, spans, scratch);
    return spans;
}

TEST(SuperquadricSpans, ARayThroughAnEllipsoidGivesOneSpanWithTheClosedFormEnds) {
    const Vec3d radii(2, 1, 0.5);
    for (const Superquadric& s : {make_superquadric(radii, 1, 1), make_superquadric(radii, 1, 1, {Twist(0, radii.z)})}) {
        const SuperquadricShape shape({s});
        // Along x through (0, 0.6, 0.3): x² / 4 = 1 − 0.36 − 0.36, so x = ±2·sqrt(0.28).
        const double half = 2 * std::sqrt(0.28);
        const auto spans = spans_of(shape, {-5, 0.6, 0.3}, {2, 0, 0}, 0, 100);
        ASSERT_EQ(spans.size(), 1u);
        EXPECT_NEAR(spans[0].enter.t, (5 - half) / 2, 1e-12);
        EXPECT_NEAR(spans[0].exit.t, (5 + half) / 2, 1e-12);
        EXPECT_EQ(spans[0].enter.primitive, 0u);
        EXPECT_TRUE(spans[0].exit.on_surface());
        EXPECT_LT(shape.boundary_normal({-5, 0.6, 0.3}, {2, 0, 0}, spans[0].enter).x, 0);
        EXPECT_GT(shape.boundary_normal({-5, 0.6, 0.3}, {2, 0, 0}, spans[0].exit).x, 0);
        // From inside: the span starts with a cut at t_min.
        const auto inside = spans_of(shape, {0, 0.6, 0.3}, {1, 0, 0}, 0.1, 100);
        ASSERT_EQ(inside.size(), 1u);
        EXPECT_FALSE(inside[0].enter.on_surface());
        EXPECT_EQ(inside[0].enter.t, 0.1);
        EXPECT_NEAR(inside[0].exit.t, half, 1e-12);
        // Cut at t_max too, and nothing outside the range.
        const auto cut = spans_of(shape, {-5, 0.6, 0.3}, {1, 0, 0}, 0, 5);
        ASSERT_EQ(cut.size(), 1u);
        EXPECT_TRUE(cut[0].enter.on_surface());
        EXPECT_EQ(cut[0].exit.primitive, BoundaryPoint::kCut);
        EXPECT_EQ(cut[0].exit.t, 5);
        EXPECT_TRUE(spans_of(shape, {-5, 0.6, 0.3}, {1, 0, 0}, 0, 1).empty());
        EXPECT_TRUE(spans_of(shape, {-5, 0.6, 0.6}, {1, 0, 0}, 0, 100).empty());
    }
}

// Inside per the spans versus the field's sign, at sample points away from the span ends.
void expect_spans_match_sampling(const SuperquadricShape& shape, const Vec3d& o, const Vec3d& d, double t_max,
                                 const std::string& what) {
    const auto spans = spans_of(shape, o, d, 0, t_max);
    for (std::size_t i = 0; i < spans.size(); ++i) {
        EXPECT_LT(spans[i].enter.t, spans[i].exit.t) << what;
        if (i > 0) {
            EXPECT_LT(spans[i - 1].exit.t, spans[i].enter.t) << what;
        }
    }
    constexpr int samples = 3000;
    for (int k = 0; k <= samples; ++k) {
        const double t = t_max * k / samples;
        bool near_end = false, in_span = false;
        for (const InsideSpan& span : spans) {
            near_end = near_end || std::abs(t - span.enter.t) < 1e-6 * t_max || std::abs(t - span.exit.t) < 1e-6 * t_max;
            in_span = in_span || (t > span.enter.t && t < span.exit.t);
        }
        if (near_end) continue;
        bool inside_any = false;
        for (const Superquadric& s : shape.superquadrics()) inside_any = inside_any || s.field(o + d * t) < 0;
        ASSERT_EQ(in_span, inside_any) << what << " at t = " << t;
    }
}

TEST(SuperquadricSpans, PinchedStarsGiveTheSpansThatDenseSamplingSees) {
    std::mt19937 random(31);
    std::uniform_real_distribution<double> unit(-1, 1), star(3, 4);
    int several = 0;
    for (int shape_index = 0; shape_index < 30; ++shape_index) {
        const Vec3d radii(1, 1.2, 0.9);
        std::vector<Deformation> stages;
        if (shape_index % 2) stages = random_deformations(random, radii);
        const SuperquadricShape shape({make_superquadric(radii, star(random), star(random), stages)});
        for (int i = 0; i < 30; ++i) {
            // Rays close to the star's arms cross them several times.
            const Vec3d o{unit(random) * 0.3, unit(random) * 0.3, 4};
            const Vec3d d = Vec3d{unit(random) * 0.2, unit(random) * 0.2, -1} - Vec3d(0, 0, 0);
            const Vec3d sideways{5 * unit(random), 5 * unit(random), unit(random) * 0.4};
            const Vec3d side_origin = sideways;
            const Vec3d side_direction = Vec3d{unit(random) * 0.3, unit(random) * 0.3, unit(random) * 0.1} - sideways * 0.2;
            expect_spans_match_sampling(shape, o, d, 8, "down " + std::to_string(shape_index));
            expect_spans_match_sampling(shape, side_origin, side_direction, 10, "side " + std::to_string(shape_index));
            if (spans_of(shape, side_origin, side_direction, 0, 10).size() > 1) ++several;
        }
    }
    EXPECT_GT(several, 10);  // the test does see multi-span rays
}

TEST(SuperquadricSpans, SeveralSuperquadricsGiveTheirUnion) {
    const SuperquadricShape shape({make_superquadric({1, 1, 1}, 1, 1),
                                   make_superquadric({1, 1, 1}, 1, 1, {}, Transform::translate({1.5, 0, 0})),
                                   make_superquadric({0.5, 0.5, 0.5}, 0.3, 0.3, {}, Transform::translate({5, 0, 0}))});
    const auto spans = spans_of(shape, {-3, 0, 0}, {1, 0, 0}, 0, 20);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_NEAR(spans[0].enter.t, 2, 1e-12);
    EXPECT_NEAR(spans[0].exit.t, 5.5, 1e-12);
    EXPECT_EQ(spans[0].enter.primitive, 0u);
    EXPECT_EQ(spans[0].exit.primitive, 1u);
    EXPECT_NEAR(spans[1].enter.t, 7.5, 1e-12);
    EXPECT_EQ(spans[1].exit.primitive, 2u);
    expect_spans_match_sampling(shape, {-3, 0.2, 0.1}, {1, 0.01, 0}, 20, "union");
}

Ray make_ray(const Vec3d& o, const Vec3d& d) {
    Ray ray;
    ray.origin = Vec3f(o);
    ray.direction = Vec3f(d);
    return ray;
}

std::unique_ptr<RenderScene> scene_with(Superquadric s, const Transform& to_world) {
    auto scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::make_unique<SuperquadricShape>(std::vector<Superquadric>{std::move(s)});
    object.to_world = to_world;
    scene->add_object(std::move(object));
    scene->commit();
    return scene;
}

TEST(SuperquadricShape, InstancedAndBakedPlacementsGiveTheSameHits) {
    const Vec3d radii(0.6, 0.8, 1.2);
    std::mt19937 random(32);
    std::uniform_real_distribution<double> unit(-1, 1);
    const std::vector<Deformation> stages = random_deformations(random, radii);
    const Transform shear = Transform::translate({0.5, 0, -1}) * Transform::rotate({0, 1, 1}, 25) *
                            Transform::scale({1, 2.5, 0.7});  // not a similarity: instanced
    const Transform similarity = Transform::translate({0.5, 0, -1}) * Transform::rotate({0, 1, 1}, 25) *
                                 Transform::scale({1.7, 1.7, 1.7});
    for (const Transform& to_world : {shear, similarity}) {
        const auto scene = scene_with(make_superquadric(radii, 0.4, 2.6, stages), to_world);
        EXPECT_EQ(scene->objects()[0].instanced, to_world.similarity_scale() == 0);
        // The reference holds the same map as its own placement and is queried directly in double.
        const Superquadric reference = make_superquadric(radii, 0.4, 2.6, stages, to_world);
        int hits = 0;
        for (int i = 0; i < 400; ++i) {
            const Vec3d o = Vec3d(Vec3f(Vec3d{unit(random), unit(random), unit(random)} * 7.0));
            const Vec3d d = Vec3d(Vec3f(to_world.point(Vec3d{unit(random), unit(random), unit(random)} * 0.8) - o));
            const auto hit = scene->intersect(make_ray(o, d), RayKind::Camera);
            SuperquadricWork work;
            const auto expected = reference.first_crossing(o, d, 0, 1e30, work);
            if (hit.has_value() != expected.has_value()) {
                // Only grazing rays may disagree, through the float ray and transforms.
                const double t = hit ? hit->t : *expected;
                EXPECT_LT(std::abs(reference.field(o + d * t)), 1e-3) << i;
                continue;
            }
            if (!hit) continue;
            ++hits;
            EXPECT_NEAR(hit->t, *expected, 1e-5 * *expected) << i;
            EXPECT_GT(dot(Vec3d(hit->geometric_normal), reference.normal(o + d * *expected)), 1 - 1e-4) << i;
            EXPECT_EQ(hit->primitive_id, 0u);
        }
        EXPECT_GT(hits, 200);
    }
}

TEST(SuperquadricShapeField, ValueIsOneLessTheGaugePositiveInside) {
    // An ellipsoid's gauge is sqrt(Σ (xᵢ/aᵢ)²): 1 − G is known everywhere inside its box.
    const Vec3d centre(0.5, -1, 2), radii(1, 2, 3);
    const SuperquadricShape shape({make_superquadric(radii, 1, 1, {}, Transform::translate(centre))});
    EXPECT_DOUBLE_EQ(*shape.field_value(centre), 1);
    EXPECT_NEAR(*shape.field_value(centre + Vec3d(0.5, 0, 0)), 0.5, 1e-12);
    EXPECT_NEAR(*shape.field_value(centre + Vec3d(0, 0, 3)), 0, 1e-12);  // on the surface
    EXPECT_NEAR(*shape.field_value(centre + Vec3d(0.6, 1.2, 0)), 1 - std::sqrt(0.36 + 0.36), 1e-12);
    EXPECT_LT(*shape.field_value(centre + Vec3d(0.9, 1.9, 0)), 0);  // outside, within the box
    EXPECT_LT(*shape.field_value(centre + Vec3d(5, 0, 0)), *shape.field_value(centre + Vec3d(2, 0, 0)));  // beyond it
    // Of a union the larger: a second, unit ball at the origin.
    const SuperquadricShape both({make_superquadric(radii, 1, 1, {}, Transform::translate(centre)),
                                  make_superquadric({1, 1, 1}, 1, 1)});
    EXPECT_NEAR(*both.field_value({0.25, 0, 0}), 0.75, 1e-12);
    EXPECT_DOUBLE_EQ(*both.field_value(centre), 1);
}

TEST(SuperquadricShapeField, DeformedOnesAreZeroOnTheirSurfaceAndTheGradientIsTheFieldsDerivative) {
    std::mt19937 random(8);
    std::uniform_real_distribution<double> exponent(0.5, 1.5), unit(-1, 1);
    for (int object = 0; object < 6; ++object) {
        const Vec3d radii(0.8, 0.6, 1.2);
        const SuperquadricShape shape({superquadric_test::random_deformed_superquadric(random, radii, exponent,
                                                                                       Transform::translate({1, 0, 0}))});
        const Superquadric& s = shape.superquadrics()[0];
        for (int i = 0; i < 40; ++i) {
            const Vec3d on_surface = s.surface_point(1.5 * unit(random), 3.1 * unit(random));
            EXPECT_NEAR(*shape.field_value(on_surface), 0, 1e-9) << object << " " << i;
        }
        // Inside, away from the coordinate planes of the undeformed frame (where the gauge has creases for these
        // exponents), the gradient against central differences of the value.
        const double h = 1e-6;
        int checked = 0;
        for (int i = 0; i < 200 && checked < 40; ++i) {
            const Vec3d p = s.surface_point(1.5 * unit(random), 3.1 * unit(random)) * 0.7 + Vec3d(0.3, 0, 0);
            const double value = *shape.field_value(p);
            if (!(value > 0.05 && value < 0.6)) continue;
            Vec3d difference;
            for (int k = 0; k < 3; ++k) {
                Vec3d step(0, 0, 0);
                step[k] = h;
                difference[k] = (*shape.field_value(p + step) - *shape.field_value(p - step)) / (2 * h);
            }
            const Vec3d gradient = shape.field_gradient(p);
            EXPECT_NEAR(length(gradient - difference), 0, 1e-4 * length(difference)) << object << " " << i;
            ++checked;
        }
        EXPECT_GT(checked, 10) << object;
    }
}

// A shadow ray that starts within a deformed shape's box (one leaving its surface) asks that shape only when nothing
// else blocks it (OcclusionPass): a ray the shape above blocks costs that shape's test alone; the answers are those
// of the nearest hit, for single rays and packets alike, also where only the shape the ray starts in blocks it.
// (Which of two primitives Embree asks first is its own affair: UserGeometryOcclusion tests the passes directly.)
TEST(SuperquadricShape, OcclusionQueriesFromWithinADeformedShapeAreAskedLast) {
    const Superquadric twisted = make_superquadric({1, 1, 1}, 0.7, 1.4, {Twist(1, 1)});
    auto scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::make_unique<SuperquadricShape>(
        std::vector<Superquadric>{twisted, make_superquadric({1, 1, 1}, 1, 1, {}, Transform::translate({0, 0, 4}))});
    scene->add_object(std::move(object));
    scene->commit();
    const auto tests = [] {
        const CounterTotals totals = counters::totals();
        const auto found = totals.geometry.find("superquadric");
        return found == totals.geometry.end() ? std::uint64_t(0) : found->second.tests;
    };
    std::mt19937 random(8);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int i = 0; i < 200; ++i) {
        // Within the twisted shape's box, outside the shape, towards the centre of the one above.
        const Vec3d origin = Vec3d(0.9, 0.9, 0.9) + Vec3d(unit(random), unit(random), unit(random)) * 0.05;
        const Vec3d towards = Vec3d(0, 0, 4) + Vec3d(unit(random), unit(random), unit(random)) * 0.2 - origin;
        ASSERT_TRUE(twisted.starts_within_deformed_box(origin, towards, 0) && !twisted.contains(origin)) << i;
        const std::uint64_t before = tests();
        EXPECT_TRUE(scene->occluded(make_ray(origin, towards))) << i;
        EXPECT_EQ(tests() - before, 1u) << i;  // the shape above, alone
    }
    for (int i = 0; i < 200; ++i) {
        std::array<Ray, 8> rays;
        for (Ray& ray : rays) {
            const Vec3d origin{0.5 * unit(random), 0.5 * unit(random), 0.5 * unit(random)};
            ray = make_ray(origin, {unit(random), unit(random), unit(random)});  // out sideways, up, or through it
            ray.t_far = i % 2 ? 0.5f : std::numeric_limits<float>::infinity();
        }
        const unsigned blocked = scene->occluded(rays, 0xFFu);
        for (std::size_t lane = 0; lane < rays.size(); ++lane) {
            const bool hit = scene->intersect(rays[lane], RayKind::Shadow).has_value();
            EXPECT_EQ(scene->occluded(rays[lane]), hit) << i << " lane " << lane;
            EXPECT_EQ(bool(blocked >> lane & 1u), hit) << i << " lane " << lane;
        }
    }
}

TEST(SuperquadricShape, CountersRecordTestsAndRootFinderWork) {
    const auto scene = scene_with(make_superquadric({1, 1, 1}, 0.7, 1.4, {Twist(1, 1)}), Transform::translate({0, 0, 5}));
    const auto count = [](const CounterTotals& t) {
        const auto found = t.geometry.find("superquadric");
        return found == t.geometry.end() ? GeometryTypeCounts{} : found->second;
    };
    const CounterTotals before = counters::totals();
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, 0}, {0, 0, 1}), RayKind::Camera));
    const CounterTotals between = counters::totals();
    ASSERT_TRUE(scene->occluded(make_ray({0, 0, 0}, {0, 0, 1})));
    const CounterTotals after = counters::totals();
    EXPECT_TRUE(count(after).counts_tests);
    EXPECT_GE(count(after).tests, count(before).tests + 2);
    EXPECT_GE(count(after).candidate_hits, count(before).candidate_hits + 2);
    const auto named = [](const CounterTotals& t, const std::string& name) {
        const auto found = t.named.find(name);
        return found == t.named.end() ? std::uint64_t(0) : found->second;
    };
    EXPECT_GT(named(after, "superquadric.evaluations"), named(before, "superquadric.evaluations"));
    // The camera ray refines the bracket of its entry; the occlusion query is settled by the bracket alone.
    EXPECT_EQ(named(between, "superquadric.refined_crossings"), named(before, "superquadric.refined_crossings") + 1);
    EXPECT_EQ(named(after, "superquadric.refined_crossings"), named(between, "superquadric.refined_crossings"));
    EXPECT_GE(named(after, "superquadric.evaluations") - named(before, "superquadric.evaluations"),
              named(after, "superquadric.halvings") - named(before, "superquadric.halvings"));
}

// ---- scene format ----------------------------------------------------------------------------------------

// The "superquadric" plugin's shape for a JSON shape object, as the scene loader would create it.
std::unique_ptr<Shape> create_shape(const std::string& json) {
    const JsonValue value = parse_json(json, "shape.json");
    auto context = std::make_shared<SceneFileContext>();
    context->file = "shape.json";
    return shape_registry().create(SceneNode(value, "shape", context));
}

TEST(SuperquadricScene, ReadsSingleAndListFormsWithDeformations) {
    std::unique_ptr<Shape> shape = create_shape(R"({"type": "superquadric",
        "superquadrics": [
          {"radii": [0.5, 0.5, 1], "exponents": [0.2, 1], "center": [3, 0, 0]},
          {"radii": [0.5, 0.5, 1], "exponents": [1, 1], "rotate": {"axis": [1, 0, 0], "angle": 90},
           "deform": [{"taper": [-0.5, 0.2]}, {"twist": 90}, {"bend": {"curvature": -0.4, "direction": 30}}]}]})");
    const auto& superquadrics = dynamic_cast<const SuperquadricShape&>(*shape).superquadrics();
    ASSERT_EQ(superquadrics.size(), 2u);
    EXPECT_EQ(superquadrics[0].shape().north_south(), 0.2);
    EXPECT_EQ(superquadrics[1].deformation().size(), 3u);
    auto scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::move(shape);
    scene->add_object(std::move(object));
    scene->commit();
    // The first one is a cylinder-like superquadric of height 2 centred at x = 3: a ray down onto it hits z = 1.
    const auto hit = scene->intersect(make_ray({3, 0, 10}, {0, 0, -1}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 9.0f, 1e-5f);
    EXPECT_EQ(hit->primitive_id, 0u);
    // The second is turned by 90 degrees about x, which takes its axis to the y axis.
    const auto side = scene->intersect(make_ray({0.01, -10, 0}, {0, 1, 0}), RayKind::Camera);
    ASSERT_TRUE(side);
    EXPECT_EQ(side->primitive_id, 1u);
    const std::unique_ptr<Shape> single = create_shape(R"({"type": "superquadric", "radii": [1, 2, 3]})");
    EXPECT_EQ(dynamic_cast<const SuperquadricShape&>(*single).superquadrics()[0].shape().radii(), Vec3d(1, 2, 3));
}

void expect_error(const std::string& shape, const std::vector<std::string>& parts) {
    SCOPED_TRACE(shape);
    const std::string message = mesh_test::input_error_message([&] { create_shape(shape); });
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
}

TEST(SuperquadricScene, BadParametersAreInputErrorsNamingTheField) {
    expect_error(R"({"type": "superquadric", "radii": [1, 0, 1]})", {"shape.radii"});
    expect_error(R"({"type": "superquadric", "radii": [1, -2, 1]})", {"shape.radii"});
    expect_error(R"({"type": "superquadric", "exponents": [0, 1]})", {"shape.exponents"});
    expect_error(R"({"type": "superquadric", "exponents": [1, 4.5]})", {"shape.exponents"});
    expect_error(R"({"type": "superquadric", "exponents": [1, 1e999]})", {"shape.json"});
    expect_error(R"({"type": "superquadric", "deform": [{"taper": -1.2}]})",
                 {"shape.deform[0]", "taper", "cross-section scale"});
    expect_error(R"({"type": "superquadric", "deform": [{"twist": 30}, {"bend": {"curvature": 1.5}}]})",
                 {"shape.deform[1]", "bend", "fold through"});
    expect_error(R"({"type": "superquadric", "deform": [{"bend": {"curvature": 0}}]})",
                 {"shape.deform[0].bend.curvature"});
    expect_error(R"({"type": "superquadric", "deform": [{"bend": {"curvature": 0.5, "region": [1, -1]}}]})",
                 {"deform[0].bend.region"});
    expect_error(R"({"type": "superquadric", "deform": [{"twist": 30, "taper": 1}]})", {"deform[0]", "one of"});
    expect_error(R"({"type": "superquadric", "deform": [{"twits": 30}]})", {"deform[0]", "twits"});
    expect_error(R"({"type": "superquadric", "radii": [1, 1, 1], "superquadrics": [{}]})", {"shape.radii", "not both"});
    expect_error(R"({"type": "superquadric", "superquadrics": []})", {"shape.superquadrics", "empty"});
    expect_error(R"({"type": "superquadric", "superquadrics": [{"radius": 1}]})", {"superquadrics[0]", "radius"});
    expect_error(R"({"type": "superquadric", "center": [2e18, 0, 0]})", {"1e18"});
}

// A deformed superquadric's surface shell grows while rays are traced: the loader charges its largest size before
// any work, so a scene of many deformed shapes that could outgrow the budget is refused at its file and field. Every
// superquadric's record (and at most its exponents' tables) is charged too, before the list is made.
TEST(SuperquadricScene, DeformedShapesChargeTheirLargestShellToTheMemoryBudget) {
    const auto load = [](const std::string& json, std::uint64_t limit) {
        const JsonValue value = parse_json(json, "shape.json");
        auto context = std::make_shared<SceneFileContext>();
        context->file = "shape.json";
        context->memory = std::make_shared<MemoryBudget>(limit);
        shape_registry().create(SceneNode(value, "shape", context));
        return context->memory;
    };
    const std::string undeformed = R"({"type": "superquadric", "superquadrics": [{}, {}, {}]})";
    const std::string twisted = R"({"type": "superquadric", "superquadrics": [{"deform": [{"twist": 90}]},
        {"deform": [{"twist": 90}]}, {"deform": [{"twist": 90}]}]})";
    // A record and at most two exponents' tables.
    constexpr std::uint64_t kRecord = sizeof(Superquadric) + Superellipsoid::kMostTableBytes;
    EXPECT_EQ(load(undeformed, 1 << 20)->charged_bytes(), 3 * kRecord);
    EXPECT_EQ(load(R"({"type": "superquadric"})", 1 << 20)->charged_bytes(), kRecord);
    EXPECT_EQ(load(twisted, 4 * SurfaceShell::kMostHeapBytes)->charged_bytes(),
              3 * kRecord + 3 * SurfaceShell::kMostHeapBytes);
    const std::string message =
        mesh_test::input_error_message([&] { load(twisted, 3 * kRecord + 2 * SurfaceShell::kMostHeapBytes + 1); });
    EXPECT_NE(message.find("shape.superquadrics[2].deform"), std::string::npos) << message;
    EXPECT_NE(message.find("surface shell"), std::string::npos) << message;
    // A long list of short entries is refused before its records are made.
    std::string many = R"({"type": "superquadric", "superquadrics": [{})";
    for (int i = 1; i < 1000; ++i) many += ", {}";
    many += "]}";
    const std::string too_many = mesh_test::input_error_message([&] { load(many, 100 * kRecord); });
    EXPECT_NE(too_many.find("shape.superquadrics"), std::string::npos) << too_many;
    EXPECT_NE(too_many.find("1000 superquadric record"), std::string::npos) << too_many;
}

// A superquadric tells its first span from its entry and a point past it that the ray reaches inside: the entry bit
// for bit the listing's first span's, the exit no later; undeformed convex ones, pinched ones and deformed ones alike.
// A ray that starts inside is left to the listing.
TEST(SuperquadricSpans, TheLeadingSpanOpensWithTheFirstSpanAndEndsNoLater) {
    std::mt19937 random(31);
    std::uniform_real_distribution<double> convex(0.05, 2), any(0.05, 4), size(0.3, 1.5), unit(-1, 1), near(0, 3);
    std::array<int, 3> found{}, asked{};
    int none = 0;
    for (int k = 0; k < 60; ++k) {
        const int kind = k % 3;  // undeformed convex, undeformed of any exponents, deformed
        const Vec3d radii(size(random), size(random), size(random));
        const Transform placement = Transform::translate({unit(random), unit(random), unit(random)}) *
                                    Transform::rotate(normalize(Vec3d(unit(random), unit(random), 1)), 90 * unit(random));
        std::uniform_real_distribution<double>& exponent = kind == 0 ? convex : any;
        const double north_south = exponent(random), east_west = exponent(random);
        const SuperquadricShape shape({make_superquadric(
            radii, north_south, east_west, kind == 2 ? random_deformations(random, radii) : std::vector<Deformation>{},
            placement)});
        for (int i = 0; i < 300; ++i) {
            const superquadric_test::RandomRay local = superquadric_test::random_ray(random, radii, i % 7 == 0);
            const Vec3d origin = placement.point(local.origin), direction = placement.vector(local.direction);
            const double t_min = i % 3 == 0 ? near(random) : 0;
            const auto spans = spans_of(shape, origin, direction, t_min, 1e30);
            QueryScratch scratch;
            const LeadingSpan lead = shape.leading_span(origin, direction, t_min, 1e30, scratch);
            const std::string what = "shape " + std::to_string(k) + " ray " + std::to_string(i);
            if (lead.outcome == LeadingSpan::Outcome::None) {
                EXPECT_TRUE(spans.empty()) << what;
                ++none;
            }
            if (!spans.empty() && spans.front().enter.on_surface()) ++asked[std::size_t(kind)];
            if (!lead.found()) continue;
            ++found[std::size_t(kind)];
            ASSERT_FALSE(spans.empty()) << what;
            EXPECT_EQ(lead.span.enter.t, spans.front().enter.t) << what;
            EXPECT_EQ(lead.span.enter.primitive, spans.front().enter.primitive) << what;
            EXPECT_TRUE(lead.span.enter.on_surface()) << what;
            EXPECT_GT(lead.span.exit.t, lead.span.enter.t) << what;
            EXPECT_LE(lead.span.exit.t, spans.front().exit.t) << what;
        }
    }
    // Nearly every first span entered from outside is told.
    for (std::size_t kind = 0; kind < 3; ++kind) EXPECT_GT(found[kind], asked[kind] * 9 / 10) << kind;
    EXPECT_GT(none, 1000);

    QueryScratch scratch;
    const SuperquadricShape inside({make_superquadric({1, 1, 1}, 0.5, 0.5, {Twist(1, 1)})});
    EXPECT_EQ(inside.leading_span({0, 0, 0}, {1, 0, 0}, 0, 1e30, scratch).outcome, LeadingSpan::Outcome::Unsure);
}

// Span ends carry no normal; boundary_normal gives the superquadric's at the end, bit for bit, and a CSG carries it
// through a placement the leaf kept (not a similarity) and flips it where the leaf is subtracted.
TEST(SuperquadricSpans, NormalsAreComputedForTheEndAskedAbout) {
    const Superquadric star = make_superquadric({1, 0.8, 0.6}, 2.5, 0.4, {Twist(1, 0.6)});
    const SuperquadricShape shape({star});
    EXPECT_TRUE(shape.defers_normals(0));
    const Vec3d o(-3, 0.05, 0.1), d(1, 0.01, 0.02);
    const auto spans = spans_of(shape, o, d, 0, 100);
    ASSERT_FALSE(spans.empty());
    for (const InsideSpan& span : spans)
        for (const BoundaryPoint& end : {span.enter, span.exit})
            if (end.on_surface()) { EXPECT_EQ(shape.boundary_normal(o, d, end), star.normal(o + d * end.t)); }

    // A ball minus the unit sphere stretched by 1.5 along y: the cavity's wall faces into the cavity.
    std::vector<CsgChild> children;
    children.push_back({std::make_unique<SuperquadricShape>(std::vector{make_superquadric({2, 2, 2}, 1, 1)}), {}, {}});
    children.push_back({std::make_unique<SuperquadricShape>(std::vector{make_superquadric({1, 1, 1}, 1, 1)}),
                        Transform::scale({1, 1.5, 1}), {}});
    const CsgShape tree(CsgOperation::Difference, std::move(children));
    EXPECT_TRUE(tree.defers_normals(1));
    QueryScratch scratch;
    const Vec3d from(-1.5, 0.3, 0.2), along(1, 0, 0);
    const auto hit = tree.first_surface_point(from, along, 0, 1e30, scratch);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->part, 1u);
    const Vec3d p = from + along * hit->t;
    EXPECT_NEAR(p.x, -std::sqrt(1 - 0.04 - 0.04), 1e-12);
    const Vec3d expected = -normalize(Vec3d(p.x, p.y / 2.25, p.z));
    const Vec3d normal = tree.boundary_normal(from, along, *hit);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(normal[k], expected[k], 1e-12) << k;
}

// The cup of the CSG scene (a cylinder with a bent handle, minus a smaller cylinder raised a little): the first
// surface point a CSG settles from its first operand's entry alone is the full combination's, bit for bit.
TEST(SuperquadricScene, CsgFirstSurfacePointsAreTheFullCombinationsOnTheCup) {
    const auto single = [](Superquadric s) {
        return CsgChild{std::make_unique<SuperquadricShape>(std::vector<Superquadric>{std::move(s)}), {}, {}};
    };
    const Transform upright = Transform::rotate({1, 0, 0}, -90);
    std::vector<CsgChild> body;
    body.push_back(single(make_superquadric({0.7, 0.7, 0.8}, 0.1, 1, {}, upright)));
    std::mt19937 random(3);
    body.push_back(single(make_superquadric({0.08, 0.08, 0.62}, 0.3, 1, random_deformations(random, {0.08, 0.08, 0.62}),
                                            Transform::translate({1, 0.05, 0}) * upright)));
    std::vector<CsgChild> cup;
    cup.push_back({std::make_unique<CsgShape>(CsgOperation::Union, std::move(body)), {}, {}});
    cup.push_back(single(make_superquadric({0.6, 0.6, 0.8}, 0.1, 1, {}, Transform::translate({0, 0.1, 0}) * upright)));
    const CsgShape tree(CsgOperation::Difference, std::move(cup));
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int i = 0; i < 3000; ++i) {
        const Vec3d origin = Vec3d(unit(random), unit(random), unit(random)) * 2.5;
        const Vec3d target = Vec3d(unit(random), unit(random), unit(random)) * 0.8;
        QueryScratch scratch;
        const auto actual = tree.first_surface_point(origin, target - origin, 0, 1e30, scratch);
        const auto expected = tree.Solid::first_surface_point(origin, target - origin, 0, 1e30, scratch);
        ASSERT_EQ(actual.has_value(), expected.has_value()) << i;
        if (!actual) continue;
        EXPECT_EQ(actual->t, expected->t) << i;
        EXPECT_EQ(tree.boundary_normal(origin, target - origin, *actual),
                  tree.boundary_normal(origin, target - origin, *expected)) << i;
        EXPECT_EQ(actual->part, expected->part) << i;
    }
}

}  // namespace
}  // namespace isotrace
