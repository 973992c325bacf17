// The isosurface shape on analytic fields: exact hits and normals on spheres, tori, planes and gyroids; thin
// features (a sub-pixel spike, sin(1000 x) sheets) against a float64 brute-force oracle; tangent rays; the work
// budget; the occlusion query against first_hit; the container's boundary as surface; inside spans, CSG with an
// isosurface operand, Embree rays; the octree's cells.
#include "geometry/isosurface/isosurface_shape.h"

#include <gtest/gtest.h>

#include <iomanip>
#include <numbers>
#include <random>

#include "geometry/csg/csg_test_support.h"
#include "geometry/expression/expression_field.h"
#include "geometry/isosurface/isosurface_test_support.h"

namespace isotrace {
namespace {

using namespace isosurface_test;

constexpr std::uint32_t kEveryCell = ~0u;

std::optional<IsosurfaceShape::Hit> hit_of(const IsosurfaceShape& shape, const Vec3d& o, const Vec3d& d,
                                           IsosurfaceWork* work_out = nullptr) {
    IsosurfaceWork work;
    const auto hit = shape.first_hit(kEveryCell, o, d, 0, INFINITY, work);
    if (work_out) *work_out = work;
    return hit;
}

// The nearest hit over the cells, one at a time, as Embree asks for them.
std::optional<IsosurfaceShape::Hit> hit_by_cells(const IsosurfaceShape& shape, const Vec3d& o, const Vec3d& d) {
    std::optional<IsosurfaceShape::Hit> best;
    for (std::uint32_t i = 0; i < shape.cells().size(); ++i) {
        IsosurfaceWork work;
        const auto hit = shape.first_hit(i, o, d, 0, best ? best->t : INFINITY, work);
        if (hit && (!best || hit->t < best->t)) best = hit;
    }
    return best;
}

Vec3d random_direction(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    return normalize(Vec3d{normal(rng), normal(rng), normal(rng)});
}

void expect_relative(double actual, double expected, double tolerance, const char* what) {
    EXPECT_LE(std::abs(actual - expected), tolerance * std::max(1.0, std::abs(expected))) << what << " " << actual
                                                                                           << " vs " << expected;
}

TEST(Isosurface, SphereHitsAndNormalsAreExact) {
    const auto shape = isosurface(std::make_unique<SphereField>(1), unit_box(2));
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> offset(-0.99, 0.99);
    for (int i = 0; i < 500; ++i) {
        // A ray from 5 away aimed within the sphere's silhouette.
        const Vec3d d = random_direction(rng);
        Vec3d u, v;
        orthonormal_basis(d, u, v);
        const double a = offset(rng), b = offset(rng) * std::sqrt(1 - a * a);
        const Vec3d o = u * a + v * b - d * 5.0;
        const double expected = 5 - std::sqrt(1 - a * a - b * b);
        const auto hit = hit_of(*shape, o, d);
        ASSERT_TRUE(hit) << i;
        expect_relative(hit->t, expected, 1e-9, "t");
        const Vec3d n = normalize(o + d * expected);
        EXPECT_LE(length(hit->normal - n), 1e-9);
        const auto by_cells = hit_by_cells(*shape, o, d);
        ASSERT_TRUE(by_cells);
        expect_relative(by_cells->t, expected, 1e-9, "t by cells");
    }
}

TEST(Isosurface, TorusHitsAndNormalsAreExact) {
    const auto shape = isosurface(std::make_unique<TorusField>(1, 0.25), unit_box(1.5));
    // Along x through the tube: the outer equator; down z onto the tube's top.
    auto hit = hit_of(*shape, {-4, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(hit);
    expect_relative(hit->t, 4 - 1.25, 1e-9, "equator");
    EXPECT_LE(length(hit->normal - Vec3d{-1, 0, 0}), 1e-9);
    hit = hit_of(*shape, {0, 1, 3}, {0, 0, -1});
    ASSERT_TRUE(hit);
    expect_relative(hit->t, 3 - 0.25, 1e-9, "top");
    EXPECT_LE(length(hit->normal - Vec3d{0, 0, 1}), 1e-9);
    // Through the hole: nothing.
    EXPECT_FALSE(hit_of(*shape, {0, 0, 3}, {0, 0, -1}));
    // Oblique, in the tube's plane through its centre circle (a circle of radius 0.25 about (0, 1, 0)).
    const Vec3d d = normalize(Vec3d{0, 1, -1});
    hit = hit_of(*shape, Vec3d{0, 1, 0} - d * 3.0, d);
    ASSERT_TRUE(hit);
    expect_relative(hit->t, 3 - 0.25, 1e-9, "oblique");
    EXPECT_LE(length(hit->normal + d), 1e-9);
}

TEST(Isosurface, PlaneHitIsExact) {
    const Vec3d n = normalize(Vec3d{1, 2, 3});
    const auto shape = isosurface(std::make_unique<PlaneField>(n, 0.1), unit_box(1));
    std::mt19937_64 rng(2);
    for (int i = 0; i < 200; ++i) {
        const Vec3d o = n * 0.5 + random_direction(rng) * 0.1;
        Vec3d d = random_direction(rng);
        if (dot(d, n) > -0.2) d = normalize(d - n);
        const double expected = (0.1 - dot(n, o)) / dot(n, d);
        if (!shape->container().bounds().contains(o + d * expected)) continue;  // the plane leaves the box there
        const auto hit = hit_of(*shape, o, d);
        ASSERT_TRUE(hit);
        const Vec3d p = o + d * hit->t;
        expect_relative(hit->t, expected, 1e-9, "plane");
        EXPECT_LE(length(hit->normal - n), 1e-12);
        EXPECT_LE(std::abs(dot(n, p) - 0.1), 1e-12);
    }
}

TEST(Isosurface, GyroidHitsAgreeWithTheOracleAndLieOnTheSurface) {
    GyroidField gyroid(3);
    const auto shape = isosurface(std::make_unique<GyroidField>(3), unit_box(1));
    std::mt19937_64 rng(3);
    int compared = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3d d = random_direction(rng);
        const Vec3d o = random_direction(rng) * 0.3 - d * 4.0;
        const auto expected = oracle_first_crossing(gyroid, shape->container(), o, d, 1e-4, {}, 0);
        const auto hit = hit_of(*shape, o, d);
        ASSERT_EQ(bool(hit), bool(expected)) << i;
        if (!hit) continue;
        ++compared;
        expect_relative(hit->t, *expected, 1e-9, "gyroid");
        const Vec3d p = o + d * hit->t;
        if (!(shape->container().signed_distance(p) < -1e-9)) continue;  // on the box: the box's normal
        EXPECT_LE(length(hit->normal - normalize(gyroid.gradient(p))), 1e-9);
    }
    EXPECT_GT(compared, 200);
}

// The occlusion query answers as first_hit does, cell by cell, for ranges that end anywhere: before, at or just
// past a hit, and starting on it; it refines fewer crossings (a bracket within the range settles it).
TEST(Isosurface, OcclusionAgreesWithTheFirstHit) {
    const auto shape = isosurface(std::make_unique<GyroidField>(3), unit_box(1));
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> uniform(0, 1);
    int occluded = 0, compared = 0;
    std::uint64_t refined_by_hits = 0, refined_by_occlusion = 0;
    for (int i = 0; i < 40; ++i) {
        const Vec3d d = random_direction(rng);
        const Vec3d o = random_direction(rng) * 0.3 - d * 4.0;
        const auto nearest = hit_of(*shape, o, d);
        const double t_hit = nearest ? nearest->t : 4.0;
        for (const double t_near : {0.0, t_hit, t_hit * (1 - 1e-7)}) {
            for (const float t_far : {float(t_hit), std::nextafter(float(t_hit), INFINITY), float(t_hit * 1.01),
                                      float(t_hit * (0.5 + uniform(rng))), INFINITY}) {
                for (std::uint32_t cell = 0; cell < shape->cells().size(); ++cell) {
                    IsosurfaceWork hits, occlusion;
                    const auto hit = shape->first_hit(cell, o, d, t_near, t_far, hits);
                    const bool expected = hit && float(hit->t) < t_far;
                    ASSERT_EQ(shape->occludes(cell, o, d, t_near, t_far, occlusion), expected)
                        << i << " cell " << cell << " t_near " << t_near << " t_far " << t_far;
                    occluded += expected;
                    ++compared;
                    refined_by_hits += hits.search.crossings;
                    refined_by_occlusion += occlusion.search.crossings;
                }
            }
        }
    }
    EXPECT_GT(occluded, 100);
    EXPECT_LT(occluded, compared);
    // Ranges that end at the hit leave its bracket undecided, and first_hit refines it: most of what is left.
    EXPECT_LT(refined_by_occlusion * 2, refined_by_hits);
}

// How many of `rays` random rays aimed at `target()` the isosurface misses or hits later than the oracle (or hits
// where the function does not change sign).
int thin_feature_misses(const ImplicitField& field, const IsosurfaceShape& shape, int rays,
                        const std::function<Vec3d(std::mt19937_64&)>& target, double step,
                        const std::function<std::vector<Window>(const Vec3d&, const Vec3d&)>& windows, double fine_step) {
    std::mt19937_64 rng(4);
    int misses = 0;
    for (int i = 0; i < rays; ++i) {
        const Vec3d d = random_direction(rng);
        const Vec3d o = target(rng) - d * 3.0;
        const auto expected = oracle_first_crossing(field, shape.container(), o, d, step, windows(o, d), fine_step);
        IsosurfaceWork work;
        const auto hit = hit_of(shape, o, d, &work);
        EXPECT_FALSE(work.budget_exhausted) << i;
        if (expected && (!hit || hit->t > *expected * (1 + 1e-9))) {
            ++misses;
            ADD_FAILURE() << "ray " << i << " expected " << *expected << " got " << (hit ? hit->t : -1.0) << std::setprecision(17) << " o " << o.x << " " << o.y << " " << o.z << " d " << d.x << " " << d.y << " " << d.z;
        } else if (hit && (!expected || hit->t < *expected * (1 - 1e-9))) {
            // An earlier hit than the oracle saw must be a real sign change (or the container's boundary).
            const double delta = 1e-9 * hit->t;
            const bool changes = (field.value(o + d * (hit->t - delta)) < 0) != (field.value(o + d * (hit->t + delta)) < 0);
            if (!changes && std::abs(shape.container().signed_distance(o + d * hit->t)) > 1e-9) {
                ++misses;
                ADD_FAILURE() << "ray " << i << " hit at " << hit->t << " where f does not change sign";
            }
        }
    }
    return misses;
}

// The search drops a contact narrower than its resolution (two crossings closer than that, the rule for tangent
// contacts); below the oracle's finest step, every contact the oracle can see must be found.
IsosurfaceSettings below_the_oracle(double fine_step) {
    IsosurfaceSettings settings;
    settings.resolution = fine_step / 10;
    return settings;
}

TEST(Isosurface, ASubPixelSpikeIsNeverMissed) {
    const double width = 1e-4, spike = 1.6;
    SpikedSphereField field(width, spike);
    const auto shape = isosurface(std::make_unique<SpikedSphereField>(width, spike),
                                  Container::box({-1.1, -1.1, -1.1}, {1.7, 1.1, 1.1}), below_the_oracle(1e-7));
    std::normal_distribution<double> near_axis(0, 1.5 * width);
    std::uniform_real_distribution<double> along(0.9, 1.65);
    // Rays aimed at points about the spike's axis; the oracle samples finely where the ray passes within 3 widths.
    const auto windows = [&](const Vec3d& o, const Vec3d& d) {
        const double dyz2 = d.y * d.y + d.z * d.z;
        if (dyz2 == 0) return std::vector<Window>{{0, 10}};
        const double t_close = -(o.y * d.y + o.z * d.z) / dyz2;
        const double miss = std::hypot(o.y + d.y * t_close, o.z + d.z * t_close);
        if (miss > 3 * width) return std::vector<Window>{};
        const double half = std::sqrt(9 * width * width - miss * miss) / std::sqrt(dyz2);
        return std::vector<Window>{{t_close - half, t_close + half}};
    };
    EXPECT_EQ(thin_feature_misses(
                  field, *shape, 10000, [&](std::mt19937_64& rng) { return Vec3d{along(rng), near_axis(rng), near_axis(rng)}; },
                  1e-3, windows, 1e-7),
              0);
}

// The sheets where sin(1000 x) > −0.999 inside the unit ball, 2·10⁻⁴ thick at most, searched by `shape`.
int sine_sheet_misses(const ImplicitField& field, const IsosurfaceShape& shape) {
    std::uniform_real_distribution<double> inside(-0.7, 0.7);
    // The oracle samples finely where x is within 2e-4 of a sheet's middle (x = (3π/2 + 2πj)/1000).
    const auto windows = [](const Vec3d& o, const Vec3d& d) {
        std::vector<Window> list;
        if (d.x == 0) return std::vector<Window>{{0, 10}};
        for (int j = -200; j <= 200; ++j) {
            const double middle = (1.5 * std::numbers::pi + 2 * std::numbers::pi * j) / 1000;
            const double a = (middle - 6e-5 - o.x) / d.x, b = (middle + 6e-5 - o.x) / d.x;
            list.push_back({std::min(a, b), std::max(a, b)});
        }
        std::sort(list.begin(), list.end(), [](const Window& p, const Window& q) { return p.lo < q.lo; });
        return list;
    };
    return thin_feature_misses(
        field, shape, 10000, [&](std::mt19937_64& rng) { return Vec3d{inside(rng), inside(rng), inside(rng)}; }, 1e-3,
        windows, 1e-6);
}

TEST(Isosurface, SineSheetsAreNeverMissed) {
    SineShellField field(1000, 0.999);
    const auto shape = isosurface(std::make_unique<SineShellField>(1000, 0.999), unit_box(1.05), below_the_oracle(1e-6));
    EXPECT_EQ(sine_sheet_misses(field, *shape), 0);
}

// The same sheets typed as an expression: its interval sines (a Taylor enclosure on narrow intervals) and its
// Newton refinement keep every sheet.
TEST(Isosurface, SineSheetsTypedAsAnExpressionAreNeverMissed) {
    const auto field = compile_expression({"max(sin(1000*x) + 0.999, length(p) - 1)", {"scene.json", 1, 1}, "f"}, {});
    const auto shape = isosurface(field, unit_box(1.05), below_the_oracle(1e-6));
    EXPECT_EQ(sine_sheet_misses(*field, *shape), 0);
}

TEST(Isosurface, TangentRaysFollowTheSearchRule) {
    // An off-centre box, so that no halving point of a ray along x falls on x = 0 by chance.
    const auto shape = isosurface(std::make_unique<SphereField>(1), Container::box({-2, -2, -2}, {2.5, 2, 2}));
    // Exactly tangent: a contact of zero width is not a crossing.
    EXPECT_FALSE(hit_of(*shape, {-3, 1, 0}, {1, 0, 0}));
    EXPECT_FALSE(hit_of(*shape, {-3, 0, 1}, {1, 0, 0}));
    // A chord well above the resolution (about 4e-6 here) is found, entering and leaving.
    const auto hit = hit_of(*shape, {-3, 1 - 1e-6, 0}, {1, 0, 0});
    ASSERT_TRUE(hit);
    expect_relative(hit->t, 3 - std::sqrt(1 - (1 - 1e-6) * (1 - 1e-6)), 1e-9, "secant");
    std::vector<InsideSpan> spans;
    QueryScratch scratch;
    shape->inside_spans({-3, 1 - 1e-6, 0}, {1, 0, 0}, 0, 10, spans, scratch);
    ASSERT_EQ(spans.size(), 1u);
    // A chord below the resolution, which no sample of f sees: not reported (and found quickly).
    IsosurfaceWork work;
    EXPECT_FALSE(hit_of(*shape, {-3, 1 - 1e-14, 0}, {1, 0, 0}, &work));
    EXPECT_LT(work.search.evaluations, 2000u);
    EXPECT_FALSE(work.budget_exhausted);
}

// sin(kx) − sin(ky) + ε: positive all along the diagonal x = y, yet its interval over any box wider than about
// ε/k straddles zero, so a ray along the diagonal asks for more subdivision than any budget allows.
class DiagonalField : public ImplicitField {
public:
    double value(const Vec3d& p) const override { return std::sin(k * p.x) - std::sin(k * p.y) + epsilon; }
    Vec3d gradient(const Vec3d& p) const override { return {k * std::cos(k * p.x), -k * std::cos(k * p.y), 0}; }
    FieldBox bounds() const override { return {{-1, -1, -1}, {1, 1, 1}}; }
    bool may_reach_surface(const Vec3d&, double) const override { return true; }
    Interval value_range(const IntervalBox& b) const override {
        return sin_range(b.x * k) - sin_range(b.y * k) + epsilon;
    }
    Interval slope_range(const IntervalBox& b, const Vec3d& d) const override {
        return cos_range(b.x * k) * (k * d.x) - cos_range(b.y * k) * (k * d.y);
    }

    static constexpr double k = 1000, epsilon = 1e-3;
};

TEST(Isosurface, WorkPerRayIsBoundedByTheBudget) {
    IsosurfaceSettings settings;
    settings.max_work = 5000;
    const auto shape = isosurface(std::make_unique<DiagonalField>(), unit_box(1), settings);
    const Vec3d d = normalize(Vec3d{1, 1, 0.1});
    IsosurfaceWork work;
    EXPECT_FALSE(hit_of(*shape, Vec3d{0, 0, 0} - d * 3.0, d, &work));
    EXPECT_TRUE(work.budget_exhausted);
    const std::uint64_t spent = work.search.evaluations + work.search.interval_bounds + work.search.slope_bounds;
    EXPECT_LT(spent, 5000u + 100 * 200);  // the budget, then at most the brackets on the stack refined
    // Twice the budget, about twice the work: the budget is what ends the search.
    settings.max_work = 10000;
    const auto larger = isosurface(std::make_unique<DiagonalField>(), unit_box(1), settings);
    IsosurfaceWork more;
    hit_of(*larger, Vec3d{0, 0, 0} - d * 3.0, d, &more);
    EXPECT_GT(more.search.evaluations, work.search.evaluations * 3 / 2);
    // A sphere is found well within the default budget.
    const auto sphere = isosurface(std::make_unique<SphereField>(1), unit_box(2));
    IsosurfaceWork easy;
    ASSERT_TRUE(hit_of(*sphere, {0.2, 0.1, -3}, {0, 0, 1}, &easy));
    EXPECT_FALSE(easy.budget_exhausted);
    EXPECT_LT(easy.search.evaluations, 200u);
}

TEST(Isosurface, TheContainerIsSurfaceWhereTheFunctionIsNegative) {
    // The gyroid cut by a ball: a ray entering the ball where f < 0 hits the ball with its normal.
    GyroidField gyroid(3);
    const auto shape = isosurface(std::make_unique<GyroidField>(3), Container::sphere({0, 0, 0}, 1));
    std::mt19937_64 rng(5);
    int on_ball = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3d d = random_direction(rng);
        const Vec3d o = d * -3.0;
        const bool negative_at_entry = gyroid.value(o + d * 2.0) < 0;
        const auto hit = hit_of(*shape, o, d);
        ASSERT_TRUE(hit);  // through the centre, the ray meets the gyroid inside the ball anyway
        if (negative_at_entry) {
            ++on_ball;
            expect_relative(hit->t, 2, 1e-12, "ball entry");
            EXPECT_LE(length(hit->normal + d), 1e-12);
        } else {
            EXPECT_GT(hit->t, 2);
        }
    }
    EXPECT_GT(on_ball, 20);
    // From inside the solid, a ray leaves through the ball.
    Vec3d start{0, 0, 0.9};
    while (gyroid.value(start) >= 0) start.x -= 0.01;
    const auto from_inside = hit_of(*shape, start, {0, 0, 1});
    ASSERT_TRUE(from_inside);
    EXPECT_GT(from_inside->t, 0);
}

TEST(Isosurface, InsideSpansOfASphereAndOfTheCutGyroid) {
    const auto shape = isosurface(std::make_unique<SphereField>(1), unit_box(2));
    std::vector<InsideSpan> spans;
    QueryScratch scratch;
    shape->inside_spans({-3, 0.6, 0}, {1, 0, 0}, 0, 10, spans, scratch);
    ASSERT_EQ(spans.size(), 1u);
    expect_relative(spans[0].enter.t, 3 - 0.8, 1e-12, "enter");
    expect_relative(spans[0].exit.t, 3 + 0.8, 1e-12, "exit");
    EXPECT_LE(length(spans[0].exit.normal - Vec3d{0.8, 0.6, 0}), 1e-9);
    // Clipped by the query range: cut ends.
    spans.clear();
    shape->inside_spans({-3, 0.6, 0}, {1, 0, 0}, 3, 10, spans, scratch);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_FALSE(spans[0].enter.on_surface());
    EXPECT_TRUE(spans[0].exit.on_surface());
    // A ball-shaped container cutting a plane's half space: the ends on the ball lie on the surface.
    const auto half_ball = isosurface(std::make_unique<PlaneField>(Vec3d{0, 0, 1}, 0), Container::sphere({0, 0, 0}, 1));
    spans.clear();
    half_ball->inside_spans({-3, 0, -0.6}, {1, 0, 0}, 0, 10, spans, scratch);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_TRUE(spans[0].enter.on_surface());
    EXPECT_TRUE(spans[0].exit.on_surface());
    expect_relative(spans[0].enter.t, 3 - 0.8, 1e-12, "ball enter");
    EXPECT_LE(length(spans[0].enter.normal - Vec3d{-0.8, 0, -0.6}), 1e-12);
}

TEST(Isosurface, IsACsgOperand) {
    // A box minus an isosurface ball: a ray along x enters the box, leaves it into the ball's hole, re-enters.
    using namespace csg_test;
    auto hole = isosurface(std::make_unique<SphereField>(0.5), unit_box(1));
    const auto scene = scene_of(csg(CsgOperation::Difference, child(box({0, 0, 0}, {1, 1, 1})), child(std::move(hole))));
    const std::vector<SurfaceHit> hits = hit_sequence(*scene, make_ray({-3, 0, 0}, {1, 0, 0}));
    ASSERT_EQ(hits.size(), 4u);
    const double expected[] = {2, 2.5, 3.5, 4};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(hits[i].t, expected[i], 1e-5) << i;
    expect_near(hits[1].geometric_normal, {1, 0, 0}, 1e-5, "the hole's wall faces into the hole");
}

TEST(Isosurface, EmbreeRaysFindTheSurface) {
    using namespace csg_test;
    const auto scene = scene_of(isosurface(std::make_unique<TorusField>(1, 0.25), unit_box(1.5)));
    const auto hit = scene->intersect(make_ray({-4, 0, 0}, {1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.75, 1e-5);
    expect_near(hit->geometric_normal, {-1, 0, 0}, 1e-6, "normal");
    EXPECT_FALSE(scene->intersect(make_ray({0, 0, 3}, {0, 0, -1}), RayKind::Camera));
    EXPECT_TRUE(scene->occluded(make_ray({0, 1, 3}, {0, 0, -1})));
    EXPECT_FALSE(scene->occluded(make_ray({0, 1, 3}, {0, 0, -1}, 0, 2)));
}

TEST(Isosurface, TheOctreeKeepsOnlyCellsThatMayHoldTheSurface) {
    SphereField sphere(1);
    MemoryBudget memory;
    const std::vector<IntervalBox> cells = surface_cells(sphere, unit_box(2), {5, 1 << 16}, memory);
    EXPECT_GT(cells.size(), 100u);
    EXPECT_LT(cells.size(), 32u * 32 * 32 / 4);  // a shell, not the volume
    std::mt19937_64 rng(6);
    for (int i = 0; i < 1000; ++i) {
        const Vec3d p = random_direction(rng);
        EXPECT_TRUE(std::any_of(cells.begin(), cells.end(), [&](const IntervalBox& c) { return c.contains(p); }));
    }
    // No surface in the container: no cell.
    EXPECT_TRUE(surface_cells(sphere, Container::box({3, 3, 3}, {4, 4, 4}), {5, 1 << 16}, memory).empty());
    // The cell limit stops the subdivision at the last level within it, counting the cells kept (a level with
    // more candidates than the limit but fewer cells kept is made).
    EXPECT_LE(surface_cells(sphere, unit_box(2), {8, 1000}, memory).size(), 1000u);
    const std::size_t level_5 = cells.size();
    EXPECT_EQ(surface_cells(sphere, unit_box(2), {5, level_5}, memory).size(), level_5);
    EXPECT_LT(surface_cells(sphere, unit_box(2), {5, level_5 - 1}, memory).size(), level_5);
    // A small budget is refused with an InputError.
    MemoryBudget tiny(1000);
    EXPECT_THROW(surface_cells(sphere, unit_box(2), {6, 1 << 16}, tiny), InputError);
}

TEST(Isosurface, ItsFieldIsTheClippedSolid) {
    const auto shape = isosurface(std::make_unique<SphereField>(1), Container::box({-2, -2, 0}, {2, 2, 2}));
    const std::unique_ptr<ImplicitField> field = shape->implicit_field();
    EXPECT_LT(field->value({0, 0, 0.5}), 0);
    EXPECT_GT(field->value({0, 0, -0.5}), 0);  // below the box
    EXPECT_NEAR(field->value({0, 0, 1}), 0, 1e-15);
    EXPECT_LE(length(field->gradient({0, 0, 1}) - Vec3d{0, 0, 1}), 1e-12);
    EXPECT_NEAR(*shape->field_value({0, 0, 0.5}), 0.5, 1e-15);
    const Interval range = field->value_range({{-0.1, 0.1}, {-0.1, 0.1}, {0.4, 0.6}});
    EXPECT_LT(range.hi, 0);
    EXPECT_TRUE(field->value_range({{-0.1, 0.1}, {-0.1, 0.1}, {-0.1, 0.1}}).contains(0));
    EXPECT_TRUE(field->may_reach_surface({0, 0, 1}, 0.01));
    EXPECT_FALSE(field->may_reach_surface({0, 0, 0.5}, 0.1));
}

}  // namespace
}  // namespace isotrace
