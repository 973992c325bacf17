// Ray slices of one element: the pieces' quadratics against the distance at points on the ray, their order and
// regions, the exact support interval (no point with dist < R is left out, nothing beyond it is let in),
// unnormalised directions, and the metaball, hard-cube, axis-aligned, near-miss and degenerate cases.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "geometry/implicit/field_function.h"
#include "geometry/implicit/implicit_test_support.h"
#include "geometry/implicit/metacube_ray_slices.h"
#include "geometry/sphere/sphere_intersection.h"

namespace isotrace {
namespace {

struct RandomRay {
    Vec3d origin, direction;
};

// Origins around the element, directions of random length (0.1 to 10) aimed roughly at it.
RandomRay random_ray(std::mt19937_64& rng, const Metacube& element) {
    std::uniform_real_distribution<double> log_length(std::log(0.1), std::log(10.0));
    const Vec3d origin = element.centre() + random_vector(rng, -5, 5);
    const Vec3d target = element.centre() + random_vector(rng, -2, 2);
    return {origin, normalize(target - origin) * std::exp(log_length(rng))};
}

TEST(MetacubeRaySlices, PiecesReproduceTheSquaredDistanceAndAreOrderedAndContiguous) {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(0, 1);
    int hits = 0, multi_piece = 0;
    for (int i = 0; i < 3000; ++i) {
        const Metacube element = random_metacube(rng);
        const RandomRay ray = random_ray(rng, element);
        const auto slices = MetacubeRaySlices::slice(element, ray.origin, ray.direction);
        if (!slices) continue;
        ++hits;
        const auto pieces = slices->pieces();
        ASSERT_GE(pieces.size(), 1u);
        ASSERT_LE(pieces.size(), std::size_t(MetacubeRaySlices::kMaxPieces));
        multi_piece += pieces.size() > 1;
        EXPECT_EQ(pieces.front().t_begin, slices->t_in());
        EXPECT_EQ(pieces.back().t_end, slices->t_out());
        for (std::size_t p = 0; p < pieces.size(); ++p) {
            const RegionPiece& piece = pieces[p];
            EXPECT_LT(piece.t_begin, piece.t_end);
            if (p + 1 < pieces.size()) {
                EXPECT_EQ(piece.t_end, pieces[p + 1].t_begin);
            }
            // 1e-12 relative, plus two rounding effects that grow where dist² is far smaller than its terms: the
            // expanded quadratic's own evaluation error (a few ulps of its largest term), and rounding the point's
            // coordinates (~1e-15 of their size, both sides do it), which moves dist² by about 2·dist·δp.
            auto tolerance = [&](const QuadraticAbout& q, double t, double expected) {
                const double s = t - q.t_ref;
                const double terms = std::abs(q.c0) + std::abs(q.c1 * s) + q.c2 * s * s;
                const double coordinate_error =
                    1e-15 * (length(ray.origin - element.centre()) + length(ray.direction * t) + 1);
                return 1e-12 * expected + 1e-15 * terms + 2 * std::sqrt(expected) * coordinate_error;
            };
            const QuadraticAbout from_start = slices->distance_squared(piece, piece.t_begin);
            const QuadraticAbout from_middle = slices->distance_squared(piece, 0.5 * (piece.t_begin + piece.t_end));
            for (int n = 0; n < 10; ++n) {
                const double t = piece.t_begin + u(rng) * (piece.t_end - piece.t_begin);
                const double expected = element.distance_squared(ray.origin + ray.direction * t);
                EXPECT_NEAR(from_start(t), expected, tolerance(from_start, t, expected));
                EXPECT_NEAR(from_middle(t), expected, tolerance(from_middle, t, expected));
            }
            // The region vector is the paper's classification of the points of the piece.
            const double middle = 0.5 * (piece.t_begin + piece.t_end);
            const Vec3d local = element.skeleton().to_local(ray.origin + ray.direction * middle);
            for (int k = 0; k < 3; ++k) {
                const double d = element.half_size()[k];
                const int expected = d == 0 ? 1 : (local[k] > d ? 1 : (local[k] < -d ? -1 : 0));
                if (std::abs(std::abs(local[k]) - d) > 1e-9) {
                    EXPECT_EQ(piece.region[k], expected);
                }
            }
        }
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(multi_piece, 500);
}

TEST(MetacubeRaySlices, SupportIntervalIsExactlyWhereTheDistanceIsWithinTheRadius) {
    std::mt19937_64 rng(22);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 2000; ++i) {
        const Metacube element = random_metacube(rng);
        const RandomRay ray = random_ray(rng, element);
        const auto slices = MetacubeRaySlices::slice(element, ray.origin, ray.direction);
        const double radius2 = element.radius() * element.radius();
        // Every point of the line with dist < R lies in [t_in, t_out]; every point of the interval has dist ≤ R.
        const double span = 20 / length(ray.direction);
        for (int n = 0; n < 200; ++n) {
            const double t = (2 * u(rng) - 1) * span;
            const double d2 = element.distance_squared(ray.origin + ray.direction * t);
            if (d2 < radius2 * (1 - 1e-9)) {
                ASSERT_TRUE(slices.has_value());
                EXPECT_GE(t, slices->t_in());
                EXPECT_LE(t, slices->t_out());
            }
        }
        if (!slices) continue;
        for (double t : {slices->t_in(), slices->t_out()})
            EXPECT_NEAR(element.distance_squared(ray.origin + ray.direction * t), radius2, 1e-9 * radius2);
        for (int n = 0; n < 20; ++n) {
            const double t = slices->t_in() + u(rng) * (slices->t_out() - slices->t_in());
            EXPECT_LE(element.distance_squared(ray.origin + ray.direction * t), radius2 * (1 + 1e-9));
        }
    }
}

TEST(MetacubeRaySlices, ScalingTheDirectionScalesTheParameters) {
    std::mt19937_64 rng(23);
    for (int i = 0; i < 500; ++i) {
        const Metacube element = random_metacube(rng);
        const RandomRay ray = random_ray(rng, element);
        const auto unit = MetacubeRaySlices::slice(element, ray.origin, normalize(ray.direction));
        const auto scaled = MetacubeRaySlices::slice(element, ray.origin, ray.direction);
        ASSERT_EQ(unit.has_value(), scaled.has_value());
        if (!unit) continue;
        const double scale = length(ray.direction);
        EXPECT_NEAR(scaled->t_in() * scale, unit->t_in(), 1e-9 * (1 + std::abs(unit->t_in())));
        EXPECT_NEAR(scaled->t_out() * scale, unit->t_out(), 1e-9 * (1 + std::abs(unit->t_out())));
        ASSERT_EQ(unit->pieces().size(), scaled->pieces().size());
        for (std::size_t p = 0; p < unit->pieces().size(); ++p)
            EXPECT_EQ(unit->pieces()[p].region, scaled->pieces()[p].region);
    }
}

TEST(MetacubeRaySlices, MetaballIsOnePieceBetweenTheSphereRoots) {
    const Vec3d centre{0.5, -1, 2}, origin{-3, 0.2, 1}, direction{2, -0.3, 0.5};
    const auto slices = MetacubeRaySlices::slice(Metacube::metaball(centre, 1.5, 1), origin, direction);
    const auto roots = intersect_sphere(origin, direction, centre, 1.5);
    ASSERT_TRUE(slices && roots);
    ASSERT_EQ(slices->pieces().size(), 1u);
    EXPECT_EQ(slices->pieces()[0].region, (std::array<int, 3>{1, 1, 1}));
    EXPECT_NEAR(slices->t_in(), roots->t0, 1e-14);
    EXPECT_NEAR(slices->t_out(), roots->t1, 1e-14);
}

// The march joins metaballs without building their slices: their dist² must be the very bits the slices give, or
// the images would change with the representation.
TEST(MetacubeRaySlices, MetaballSquaredDistanceWithoutSlicesIsBitIdentical) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> radius(0.05, 3), t(-10, 10);
    int compared = 0;
    for (int i = 0; i < 2000; ++i) {
        const Metacube element = Metacube::metaball(random_vector(rng, -20, 20), radius(rng), 1);
        const RandomRay ray = random_ray(rng, element);
        const auto slices = MetacubeRaySlices::slice(element, ray.origin, ray.direction);
        if (!slices) continue;
        ++compared;
        const double t_ref = t(rng);
        const QuadraticAbout with = slices->distance_squared(slices->pieces()[0], t_ref);
        const QuadraticAbout without =
            MetacubeRaySlices::metaball_distance_squared(ray.origin, ray.direction, element.centre(), t_ref);
        EXPECT_EQ(with.t_ref, without.t_ref);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(with.c0), std::bit_cast<std::uint64_t>(without.c0));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(with.c1), std::bit_cast<std::uint64_t>(without.c1));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(with.c2), std::bit_cast<std::uint64_t>(without.c2));
    }
    EXPECT_GT(compared, 1000);
}

TEST(MetacubeRaySlices, AxisAlignedRayCrossesFaceRegionBodyAndFaceRegion) {
    OrientedBox box;
    box.half_size = {1, 1, 1};
    const auto slices = MetacubeRaySlices::slice(Metacube(box, 0.5, 1), {-5, 0.2, -0.3}, {2, 0, 0});
    ASSERT_TRUE(slices);
    const auto pieces = slices->pieces();
    ASSERT_EQ(pieces.size(), 3u);
    EXPECT_DOUBLE_EQ(pieces[0].t_begin, 1.75);
    EXPECT_DOUBLE_EQ(pieces[1].t_begin, 2);
    EXPECT_DOUBLE_EQ(pieces[2].t_begin, 3);
    EXPECT_DOUBLE_EQ(pieces[2].t_end, 3.25);
    EXPECT_EQ(pieces[0].region, (std::array<int, 3>{-1, 0, 0}));
    EXPECT_EQ(pieces[1].region, (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(pieces[2].region, (std::array<int, 3>{1, 0, 0}));
    const QuadraticAbout body = slices->distance_squared(pieces[1], 2.5);
    EXPECT_EQ(body.c0, 0);
    EXPECT_EQ(body.c1, 0);
    EXPECT_EQ(body.c2, 0);
    const QuadraticAbout face = slices->distance_squared(pieces[2], 3);  // (2s)² with s = t − 3
    EXPECT_EQ(face.c0, 0);
    EXPECT_EQ(face.c1, 0);
    EXPECT_EQ(face.c2, 4);
}

TEST(MetacubeRaySlices, HardCubeSupportIsTheBoxWithZeroDistance) {
    OrientedBox box;
    box.half_size = {1, 0.5, 2};
    const auto slices = MetacubeRaySlices::slice(Metacube(box, 0, 1), {0.3, -4, 0.1}, {0, 1, 0});
    ASSERT_TRUE(slices);
    ASSERT_EQ(slices->pieces().size(), 1u);
    EXPECT_DOUBLE_EQ(slices->t_in(), 3.5);
    EXPECT_DOUBLE_EQ(slices->t_out(), 4.5);
    EXPECT_EQ(slices->pieces()[0].region, (std::array<int, 3>{0, 0, 0}));
}

TEST(MetacubeRaySlices, LinesThatMissTheRoundedSupportHaveNoSlices) {
    OrientedBox box;
    box.half_size = {1, 1, 1};
    const Metacube element(box, 1, 1);
    // Inside the box grown by R near its vertical edge, but sqrt(2)·0.9 > R from the box's edge.
    EXPECT_FALSE(MetacubeRaySlices::slice(element, {1.9, 1.9, -5}, {0, 0, 1}));
    EXPECT_FALSE(MetacubeRaySlices::slice(element, {3, 0, -5}, {0, 0, 1}));
    EXPECT_FALSE(MetacubeRaySlices::slice(element, {2.0001, 0, -5}, {0, 0, 1}));
    EXPECT_FALSE(MetacubeRaySlices::slice(element, {0, 0, 0}, {0, 0, 0}));   // no direction
    EXPECT_TRUE(MetacubeRaySlices::slice(element, {1.6, 1.6, -5}, {0, 0, 1}));
}

// What the intersector builds on: on each piece, the kernel's polynomial in r² composed with the piece's
// quadratic gives the element's field along the ray.
TEST(MetacubeRaySlices, KernelPolynomialOfThePieceQuadraticIsTheField) {
    std::mt19937_64 rng(24);
    std::uniform_real_distribution<double> u(0, 1);
    const auto kim = make_field_function("kim", 0);
    for (int i = 0; i < 300; ++i) {
        const Metacube element = random_metacube(rng);
        const RandomRay ray = random_ray(rng, element);
        const auto slices = MetacubeRaySlices::slice(element, ray.origin, ray.direction);
        if (!slices) continue;
        const FieldPiece polynomial = kim->pieces(element.radius()).pieces[0];
        for (const RegionPiece& piece : slices->pieces()) {
            const QuadraticAbout r2 = slices->distance_squared(piece, piece.t_begin);
            const double t = piece.t_begin + u(rng) * (piece.t_end - piece.t_begin);
            double f = 0;
            for (int k = polynomial.degree; k >= 0; --k) f = f * r2(t) + polynomial.coefficients[k];
            EXPECT_NEAR(element.weight() * f, element.field(*kim, ray.origin + ray.direction * t), 1e-12);
        }
    }
}

}  // namespace
}  // namespace isotrace
