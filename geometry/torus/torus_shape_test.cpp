// Tori: crossings in double against closed forms and against a long-double sphere-tracing oracle to 1e-9 relative,
// for near rays, rays from far away, rays along and parallel to the axis, grazing rays and thin tori (r/R = 1e-3);
// inside spans; uv and its derivatives; baked and instanced transforms through a real RenderScene; the exact distance
// field; counters; and the scene-format errors of the "torus" plugin.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "geometry/cone/round_shapes_test_support.h"
#include "geometry/csg/csg_test_support.h"
#include "geometry/mesh/mesh_test_support.h"
#include "geometry/torus/torus_shape.h"
#include "renderer/core/render_counters.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

using csg_test::expect_near;
using csg_test::make_ray;

Torus make_torus(const Vec3d& centre, const Vec3d& axis, double major, double minor) {
    Torus torus;
    static_cast<AxialFrame&>(torus) = AxialFrame::around(centre, normalize(axis));
    torus.major_radius = major;
    torus.minor_radius = minor;
    return torus;
}

std::vector<double> crossings_of(const Torus& torus, const Vec3d& o, const Vec3d& d, double t_min = -INFINITY,
                                 double t_max = INFINITY) {
    const TorusCrossings c = torus_crossings(torus, o, d, t_min, t_max, false);
    return {c.t.begin(), c.t.begin() + c.count};
}

using Real = long double;

// The crossings by sphere tracing the exact distance in long double, each refined by Newton steps on it. `unclear`
// is set for rays the oracle cannot settle: a crossing at a grazing angle, or a pass closer than 1e-5·R that does
// not cross.
std::vector<double> oracle_crossings(const Torus& torus, const Vec3d& origin, const Vec3d& direction, bool& unclear) {
    const Real R = torus.major_radius, r = torus.minor_radius, length_d = std::sqrt(Real(dot(direction, direction)));
    const Vec3d b = torus.binormal();
    const auto local = [&](const Vec3d& v) {
        return std::array<Real, 3>{Real(v.x) * torus.reference.x + Real(v.y) * torus.reference.y + Real(v.z) * torus.reference.z,
                                   Real(v.x) * b.x + Real(v.y) * b.y + Real(v.z) * b.z,
                                   Real(v.x) * torus.axis.x + Real(v.y) * torus.axis.y + Real(v.z) * torus.axis.z};
    };
    const auto o = local(origin - torus.origin);
    auto u = local(direction);
    for (Real& x : u) x /= length_d;
    const auto distance = [&](Real s, Real& slope) {
        const Real x = o[0] + s * u[0], y = o[1] + s * u[1], z = o[2] + s * u[2];
        const Real rho = std::sqrt(x * x + y * y), off = rho - R, tube = std::sqrt(off * off + z * z);
        slope = (off * (x * u[0] + y * u[1]) / rho + z * u[2]) / tube;
        return tube - r;
    };
    const Real nearest = -(o[0] * u[0] + o[1] * u[1] + o[2] * u[2]);
    Real s = nearest - (R + r) - 1, sign = 1;
    std::vector<double> result;
    unclear = false;
    bool close = false;    // came within 1e-5·R of the surface
    bool leaving = false;  // just crossed, not yet 1e-5·R away
    for (int step = 0; step < 1000000 && s < nearest + R + r + 1; ++step) {
        Real slope;
        const Real h = sign * distance(s, slope);
        if (h > 1e-9L * R) {
            if (leaving) {
                leaving = h < 1e-5L * R;
            } else {
                if (close && h > 1e-5L * R) unclear = true;  // came close and went away without crossing: a near miss
                close = close || h < 1e-5L * R;
            }
            s += h;
            continue;
        }
        for (int i = 0; i < 30; ++i) s -= distance(s, slope) / slope;
        if (std::abs(distance(s, slope)) > 1e-12L * R || std::abs(slope) < 0.02L) unclear = true;  // grazing
        if (unclear) return result;
        result.push_back(double(s / length_d));
        sign = -sign;
        close = false;
        leaving = true;
        s += 1e-7L * R / std::abs(slope);
    }
    return result;
}

void check_against_oracle(const Torus& torus, double distance, unsigned seed, int rays, int& hits) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    const double R = torus.major_radius, r = torus.minor_radius;
    for (int i = 0; i < rays; ++i) {
        const Vec3d o = torus.origin + normalize(Vec3d(unit(random), unit(random), unit(random))) * (distance * R);
        // Aim at a random point of the tube's neighbourhood, so that thin tori are hit too.
        const double phi = M_PI * unit(random);
        const Vec3d on_circle = torus.origin + torus.world_vector({R * std::cos(phi), R * std::sin(phi), 0});
        const Vec3d target = on_circle + Vec3d(unit(random), unit(random), unit(random)) * (1.5 * r);
        const Vec3d d = (target - o) * (0.5 + std::abs(unit(random)));
        bool unclear = false;
        const std::vector<double> expected = oracle_crossings(torus, o, d, unclear);
        if (unclear) continue;
        const std::vector<double> got = crossings_of(torus, o, d);
        ASSERT_EQ(got.size(), expected.size()) << "ray " << i;
        hits += got.empty() ? 0 : 1;
        for (std::size_t k = 0; k < got.size(); ++k) EXPECT_NEAR(got[k], expected[k], 1e-9 * std::abs(expected[k])) << "ray " << i << ", crossing " << k;
        // The first crossing after a start point is the first of the range's.
        if (expected.size() >= 2) {
            const double from = 0.5 * (expected[0] + expected[1]);
            const TorusCrossings first = torus_crossings(torus, o, d, from, INFINITY, true);
            ASSERT_EQ(first.count, 1);
            EXPECT_NEAR(first.t[0], expected[1], 1e-9 * std::abs(expected[1]));
        }
    }
}

TEST(Torus, CrossingsAgreeWithTheOracle) {
    const Torus torus = make_torus({0.3, -0.2, 0.5}, {0.3, 1, -0.4}, 1.5, 0.4);
    int hits = 0;
    check_against_oracle(torus, 4, 1, 1500, hits);
    EXPECT_GT(hits, 700);
}

TEST(Torus, CrossingsKeepTheirPrecisionForRaysFromFarAway) {
    const Torus torus = make_torus({0.3, -0.2, 0.5}, {0.3, 1, -0.4}, 1.5, 0.4);
    int hits = 0;
    check_against_oracle(torus, 1e5, 2, 1000, hits);
    EXPECT_GT(hits, 400);
}

TEST(Torus, ThinTubesAreFoundAndPrecise) {
    const Torus torus = make_torus({0, 0, 0}, {0.2, 1, 0.1}, 1, 1e-3);
    int hits = 0;
    check_against_oracle(torus, 3, 3, 1500, hits);
    EXPECT_GT(hits, 300);
    // Known answers: parallel to the axis at ρ = R + r/2, the tube is crossed where z = ±r·√3/2.
    const Torus upright = make_torus({0, 0, 0}, {0, 1, 0}, 1, 1e-3);
    const std::vector<double> c = crossings_of(upright, {1.0005, 5, 0}, {0, -1, 0});
    ASSERT_EQ(c.size(), 2u);
    EXPECT_NEAR(c[0], 5 - 1e-3 * std::sqrt(0.75), 1e-13);
    EXPECT_NEAR(c[1], 5 + 1e-3 * std::sqrt(0.75), 1e-13);
}

TEST(Torus, KnownAnswersInTheEquatorialPlaneAndAlongTheAxis) {
    const Torus torus = make_torus({0, 0, 0}, {0, 1, 0}, 2, 0.5);
    // Through the centre in the plane of the core circle: four crossings.
    for (const double distance : {10.0, 1e4, 1e7}) {
        const std::vector<double> c = crossings_of(torus, {-distance, 0, 0}, {1, 0, 0});
        ASSERT_EQ(c.size(), 4u) << distance;
        const double expected[] = {distance - 2.5, distance - 1.5, distance + 1.5, distance + 2.5};
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(c[std::size_t(k)], expected[k], 1e-15 * distance + 1e-13) << distance;
    }
    // Along the axis: through the hole, nothing; parallel to it through the tube: top and bottom.
    EXPECT_TRUE(crossings_of(torus, {0, 10, 0}, {0, -1, 0}).empty());
    EXPECT_TRUE(crossings_of(torus, {0, -1e6, 0}, {0, 1, 0}).empty());
    std::vector<double> c = crossings_of(torus, {0, -10, 2}, {0, 2, 0});
    ASSERT_EQ(c.size(), 2u);
    EXPECT_NEAR(c[0], 4.75, 1e-14);
    EXPECT_NEAR(c[1], 5.25, 1e-14);
    expect_near(Vec3f(torus_gradient(torus, {0, -0.5, 2})), {0, -1, 0}, 1e-7, "bottom normal");
    // Parallel to the axis through the inner edge of the tube's crossing plane: ρ = 1.75, z = ±√(0.25 − 0.0625).
    c = crossings_of(torus, {1.75, 3, 0}, {0, -1, 0});
    ASSERT_EQ(c.size(), 2u);
    EXPECT_NEAR(c[0], 3 - std::sqrt(0.1875), 1e-14);
    // The range: only crossings strictly inside it.
    c = crossings_of(torus, {-10, 0, 0}, {1, 0, 0}, 7.5, 11.5);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0], 8.5, 1e-14);
}

TEST(Torus, GrazingRaysHitJustInsideAndMissJustOutside) {
    const Torus torus = make_torus({0, 0, 0}, {0, 1, 0}, 2, 0.5);
    // Tangent to the outer equator (ρ = 2.5) and to the top circle (y = 0.5), each nudged in and out.
    for (const double nudge : {1e-6, 1e-9}) {
        EXPECT_EQ(crossings_of(torus, {-10, 0, 2.5 * (1 + nudge)}, {1, 0, 0}).size(), 0u) << nudge;
        EXPECT_EQ(crossings_of(torus, {-10, 0, 2.5 * (1 - nudge)}, {1, 0, 0}).size(), 2u) << nudge;
        EXPECT_EQ(crossings_of(torus, {-10, 0.5 * (1 + nudge), 0}, {1, 0, 0}).size(), 0u) << nudge;
        EXPECT_EQ(crossings_of(torus, {-10, 0.5 * (1 - nudge), 0}, {1, 0, 0}).size(), 4u) << nudge;
    }
    // The inner equator seen from inside the hole, tangentially: at ρ = 1.5 along z.
    EXPECT_EQ(crossings_of(torus, {-1.5 * (1 + 1e-6), 0, -10}, {0, 0, 1}).size(), 2u);
    EXPECT_EQ(crossings_of(torus, {-1.5 * (1 - 1e-6), 0, -10}, {0, 0, 1}).size(), 4u);
}

// ---- through a RenderScene --------------------------------------------------------------------------------

std::unique_ptr<RenderScene> torus_scene(const Torus& torus, const Transform& to_world = {}) {
    return csg_test::scene_of(std::make_unique<TorusShape>(torus), to_world);
}

TEST(TorusShape, HitsAndNormalsThroughEmbree) {
    const auto scene = torus_scene(make_torus({0, 0, 0}, {0, 1, 0}, 2, 0.5));
    auto hit = scene->intersect(make_ray({-10, 0, 0}, {1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 7.5f);
    expect_near(hit->geometric_normal, {-1, 0, 0}, 1e-6, "outer");
    hit = scene->intersect(make_ray({-10, 0, 0}, {1, 0, 0}, 9), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 11.5f);
    expect_near(hit->geometric_normal, {-1, 0, 0}, 1e-6, "inner equator on the far side");
    // From inside the tube: the exit, outward.
    hit = scene->intersect(make_ray({2, 0, 0}, {0, 1, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 0.5f);
    expect_near(hit->geometric_normal, {0, 1, 0}, 1e-6, "exit");
    EXPECT_FALSE(scene->intersect(make_ray({0, 10, 0}, {0, -1, 0}), RayKind::Camera));
    EXPECT_TRUE(scene->occluded(make_ray({-10, 0, 0}, {1, 0, 0})));
    EXPECT_FALSE(scene->occluded(make_ray({-10, 0, 0}, {1, 0, 0}, 0, 7.4f)));
}

TEST(TorusShape, InsideSpansPairTheCrossings) {
    const TorusShape shape(make_torus({0, 0, 0}, {0, 1, 0}, 2, 0.5));
    QueryScratch scratch;
    std::vector<InsideSpan> spans;
    shape.inside_spans({-10, 0, 0}, {1, 0, 0}, 0, 100, spans, scratch);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_NEAR(spans[0].enter.t, 7.5, 1e-14);
    EXPECT_NEAR(spans[0].exit.t, 8.5, 1e-14);
    EXPECT_NEAR(spans[1].enter.t, 11.5, 1e-14);
    EXPECT_NEAR(spans[1].exit.t, 12.5, 1e-14);
    expect_near(Vec3f(spans[0].exit.normal), {1, 0, 0}, 1e-12, "inner equator, near side");
    // From inside the tube, clipped: a cut, then the exit; the second span follows.
    spans.clear();
    shape.inside_spans({-10, 0, 0}, {1, 0, 0}, 8, 12, spans, scratch);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_FALSE(spans[0].enter.on_surface());
    EXPECT_FALSE(spans[1].exit.on_surface());
    // Along the axis, and grazing: nothing.
    spans.clear();
    shape.inside_spans({0, -10, 0}, {0, 1, 0}, 0, 100, spans, scratch);
    shape.inside_spans({-10, 0.5, 0}, {1, 0, 0}, 0, 100, spans, scratch);
    EXPECT_TRUE(spans.empty());
    EXPECT_TRUE(shape.solid_problem().empty());
}

TEST(TorusShape, UvDerivativesAreThoseOfTheParametrisation) {
    const Torus torus = make_torus({1, 2, 3}, {0.3, 1, 0.2}, 1.5, 0.4);
    const TorusShape shape(torus);
    const auto point = [&](double u, double v) {
        const double phi = 2 * M_PI * u, theta = 2 * M_PI * v, rho = 1.5 + 0.4 * std::cos(theta);
        return torus.origin + torus.world_vector({rho * std::cos(phi), rho * std::sin(phi), 0.4 * std::sin(theta)});
    };
    std::mt19937 random(8);
    std::uniform_real_distribution<double> unit(0.01, 0.99);
    const double h = 1e-6;
    for (int i = 0; i < 200; ++i) {
        const double u0 = unit(random), v0 = unit(random);
        const Vec3d p = point(u0, v0);
        const LocalShading s = shape.shading(RTCHit{}, Vec3f(torus_gradient(torus, p)), p);
        EXPECT_NEAR(s.uv[0], u0, 1e-6);
        EXPECT_NEAR(s.uv[1], v0, 1e-6);
        const Vec3d dpdu = (point(u0 + h, v0) - point(u0 - h, v0)) / (2 * h);
        const Vec3d dpdv = (point(u0, v0 + h) - point(u0, v0 - h)) / (2 * h);
        EXPECT_NEAR(length(Vec3d(s.dpdu) - dpdu), 0, 1e-4 * length(dpdu)) << i;
        EXPECT_NEAR(length(Vec3d(s.dpdv) - dpdv), 0, 1e-4 * length(dpdv)) << i;
        EXPECT_GT(dot(cross(dpdu, dpdv), torus_gradient(torus, p)), 0) << "dpdu × dpdv points out";
    }
}

TEST(TorusShape, SimilaritiesAreBakedOtherTransformsInstanced) {
    const Torus torus = make_torus({0, 0, 0}, {0, 1, 0}, 1, 0.3);
    const Transform similarity =
        Transform::translate({1, -2, 3}) * Transform::rotate({1, 1, 0}, 30) * Transform::scale({2.5, -2.5, 2.5});
    const Transform stretch = Transform::translate({0.5, 0, 1}) * Transform::rotate({0, 0, 1}, 20) * Transform::scale({1, 3, 0.5});
    for (const bool similar : {true, false}) {
        const Transform& to_world = similar ? similarity : stretch;
        const auto scene = torus_scene(torus, to_world);
        ASSERT_EQ(scene->objects()[0].instanced, !similar);
        const int hits = round_test::expect_hits_as_in_object_space(
            *scene, to_world, {0, 0, 0}, 12, [&](const Vec3d& o, const Vec3d& d) {
                std::vector<round_test::ObjectHit> hits;
                for (const double t : crossings_of(torus, o, d)) hits.push_back({t, torus_gradient(torus, o + d * t)});
                return hits;
            });
        EXPECT_GT(hits, 60);
    }
    const auto scene = torus_scene(torus, similarity);
    const Torus& baked = static_cast<const TorusShape&>(*scene->objects()[0].shape).torus();
    EXPECT_NEAR(length(baked.origin - Vec3d(1, -2, 3)), 0, 1e-12);
    EXPECT_NEAR(baked.major_radius, 2.5, 1e-12);
    EXPECT_NEAR(baked.minor_radius, 0.75, 1e-12);
}

TEST(TorusShape, CountersRecordTestsAndCandidateHits) {
    const auto scene = torus_scene(make_torus({0, 0, 0}, {0, 1, 0}, 2, 0.5));
    const auto count = [] {
        const auto totals = counters::totals();
        const auto found = totals.geometry.find("torus");
        return found == totals.geometry.end() ? GeometryTypeCounts{} : found->second;
    };
    const GeometryTypeCounts before = count();
    ASSERT_TRUE(scene->intersect(make_ray({-10, 0, 0}, {1, 0, 0}), RayKind::Camera));
    const GeometryTypeCounts after = count();
    EXPECT_TRUE(after.counts_tests);
    EXPECT_GE(after.tests, before.tests + 1);
    EXPECT_GE(after.candidate_hits, before.candidate_hits + 1);
}

// ---- the field -----------------------------------------------------------------------------------------------

TEST(TorusField, ExactSignedDistanceGradientAndBounds) {
    const Torus upright = make_torus({0, 0, 0}, {0, 1, 0}, 2, 0.5);
    const auto field = TorusShape(upright).implicit_field();
    EXPECT_DOUBLE_EQ(field->value({2, 0, 0}), -0.5);
    EXPECT_DOUBLE_EQ(field->value({0, 0, 0}), 1.5);
    EXPECT_DOUBLE_EQ(field->value({5, 4, 0}), 4.5);
    EXPECT_DOUBLE_EQ(field->value({0, 0, -2.25}), -0.25);
    expect_near(Vec3f(field->gradient({5, 4, 0})), {0.6, 0.8, 0}, 1e-7, "outside");
    EXPECT_NEAR(length(field->gradient({0, 0, 0})), 1, 1e-15) << "on the axis: any unit vector";
    const FieldBox box = field->bounds();
    expect_near(Vec3f(box.lower), {-2.5, -0.5, -2.5}, 1e-12, "lower");
    expect_near(Vec3f(box.upper), {2.5, 0.5, 2.5}, 1e-12, "upper");
    // A tilted torus: gradients against differences, value and slope ranges holding every sample.
    const Torus torus = make_torus({0.3, 0.1, -0.2}, {1, 2, 0.5}, 1.2, 0.3);
    const auto tilted = TorusShape(torus).implicit_field();
    std::mt19937 random(14);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int i = 0; i < 1000; ++i) {
        const Vec3d p = torus.origin + Vec3d(unit(random), unit(random), unit(random)) * 2.0;
        const double h = 1e-6;
        Vec3d numeric;
        for (int k = 0; k < 3; ++k) {
            Vec3d e{};
            e[k] = h;
            numeric[k] = (tilted->value(p + e) - tilted->value(p - e)) / (2 * h);
        }
        EXPECT_NEAR(length(tilted->gradient(p) - numeric), 0, 1e-6) << i;
    }
    round_test::expect_distance_bounds_hold(*tilted, torus.origin, 1.5, 15);
}

// ---- scene-format errors ----------------------------------------------------------------------------------

using round_test::scene_with_shape;

TEST(TorusScene, LoadsAndNormalisesTheAxis) {
    mesh_test::ScratchDirectory dir;
    const auto loaded = load_scene(dir.write("t.json", scene_with_shape(
        R"({"type": "torus", "center": [1, 2, 3], "axis": [0, 0, 5], "major_radius": 2, "minor_radius": 0.5})")));
    const Torus& torus = static_cast<const TorusShape&>(*loaded->scene->objects()[0].shape).torus();
    EXPECT_EQ(torus.origin, Vec3d(1, 2, 3));
    EXPECT_EQ(torus.axis, Vec3d(0, 0, 1));
    EXPECT_EQ(torus.major_radius, 2);
    EXPECT_EQ(torus.minor_radius, 0.5);
}

TEST(TorusScene, BadInputIsAnInputErrorAtTheKey) {
    const round_test::BadInput cases[] = {
        {R"({"type": "torus", "major_radius": 0})", "objects[0].shape.major_radius"},
        {R"({"type": "torus", "minor_radius": -0.1})", "objects[0].shape.minor_radius"},
        {R"({"type": "torus", "major_radius": 1, "minor_radius": 1})", "objects[0].shape.minor_radius"},
        {R"({"type": "torus", "major_radius": 1, "minor_radius": 2})", "objects[0].shape.minor_radius"},
        {R"({"type": "torus", "axis": [0, 0, 0]})", "objects[0].shape.axis"},
        {R"({"type": "torus", "axis": [1e300, 1e300, 0]})", "objects[0].shape.axis"},
        {R"({"type": "torus", "center": [9e17, 0, 0], "major_radius": 2e17})", "objects[0].shape"},
        {R"({"type": "torus", "major_radius": NaN})", "expected a JSON value"},  // JSON has no NaN
    };
    round_test::expect_input_errors(cases);
}

TEST(Torus, CertainlyOutsideBeyondItsDistance) {
    const TorusShape torus(make_torus({0, 0, 0}, {0, 1, 0}, 1, 0.25));
    EXPECT_TRUE(torus.certainly_outside({0, 0, 0}, 0.74));  // the hole's centre: 0.75 from the tube
    EXPECT_FALSE(torus.certainly_outside({0, 0, 0}, 0.76));
    EXPECT_TRUE(torus.certainly_outside({1, 1, 0}, 0.74));  // above the tube's centre line
    EXPECT_FALSE(torus.certainly_outside({1, 0.2, 0}, 0));   // inside the tube
}

}  // namespace
}  // namespace isotrace
