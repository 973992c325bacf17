// The planes that hold star-like and pinched superellipsoids: the sum bound against Hölder's inequality, every
// surface and inner point kept, segments it rejects outside the solid all along, the octahedron's faces exactly.
#include "geometry/superquadric/enclosing_polytope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "geometry/superquadric/superellipsoid.h"

namespace isotrace {
namespace {

double p_norm(double a, double b, double p) { return std::pow(std::pow(a, p) + std::pow(b, p), 1 / p); }

Superellipsoid random_shape(std::mt19937& random) {
    std::uniform_real_distribution<double> radius(0.2, 2), exponent(Superellipsoid::kMinExponent,
                                                                      Superellipsoid::kMaxExponent);
    const Vec3d radii{radius(random), radius(random), radius(random)};
    const double e1 = exponent(random), e2 = exponent(random);
    return Superellipsoid{radii, e1, e2};
}

TEST(SuperquadricEnclosingPolytope, SumBoundIsHoldersConstantAndHolds) {
    EXPECT_EQ(EnclosingPolytope::sum_bound(0.5), 1);
    EXPECT_EQ(EnclosingPolytope::sum_bound(1), 1);
    EXPECT_NEAR(EnclosingPolytope::sum_bound(2), std::numbers::sqrt2, 1e-15);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0, 1), p(0.5, 100);
    for (int i = 0; i < 10000; ++i) {
        const double a = unit(random), b = unit(random), q = p(random);
        EXPECT_LE(a + b, EnclosingPolytope::sum_bound(q) * p_norm(a, b, q) * (1 + 1e-12)) << a << " " << b << " " << q;
    }
    // Equality on the diagonal: the bound is the least.
    for (const double q : {1.0, 1.5, 2.0, 7.0})
        EXPECT_NEAR(2.0, EnclosingPolytope::sum_bound(q) * p_norm(1, 1, q), 1e-12) << q;
}

TEST(SuperquadricEnclosingPolytope, OnlyShapesWithAnExponentAboveOneHavePlanes) {
    EXPECT_TRUE((Superellipsoid{{1, 1, 1}, 1, 1}.enclosing_polytope().empty()));
    EXPECT_TRUE((Superellipsoid{{1, 2, 1}, 0.3, 0.02}.enclosing_polytope().empty()));
    EXPECT_FALSE((Superellipsoid{{1, 1, 1}, 1.5, 1}.enclosing_polytope().empty()));
    EXPECT_FALSE((Superellipsoid{{1, 1, 1}, 0.3, 3.5}.enclosing_polytope().empty()));
    EXPECT_FALSE((Superellipsoid{{1, 1, 1}, 4, 4}.enclosing_polytope().empty()));
}

TEST(SuperquadricEnclosingPolytope, KeepsEverySurfaceAndInnerPoint) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> eta(-std::numbers::pi / 2, std::numbers::pi / 2),
        omega(-std::numbers::pi, std::numbers::pi), shrink(0, 1), unit(-1, 1);
    for (int shape = 0; shape < 200; ++shape) {
        const Superellipsoid s = random_shape(random);
        const EnclosingPolytope& planes = s.enclosing_polytope();
        for (int i = 0; i < 200; ++i) {
            const Vec3d surface = s.surface_point(eta(random), omega(random));
            const Vec3d direction = normalize(Vec3d{unit(random), unit(random), unit(random)});
            EXPECT_FALSE(planes.misses(surface, direction, 0)) << shape << " " << i;
            EXPECT_FALSE(planes.misses(surface * shrink(random), direction, 0)) << shape << " " << i;
            // A segment through the point, starting before it.
            EXPECT_FALSE(planes.misses(surface - direction * 0.5, direction, 1)) << shape << " " << i;
        }
    }
}

TEST(SuperquadricEnclosingPolytope, RejectedSegmentsStayOutsideTheSolid) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1, 1);
    int rejected = 0;
    for (int shape = 0; shape < 100; ++shape) {
        const Superellipsoid s = random_shape(random);
        const Vec3d r = s.radii();
        for (int i = 0; i < 200; ++i) {
            const Vec3d start{r.x * unit(random), r.y * unit(random), r.z * unit(random)};
            const Vec3d end{r.x * unit(random), r.y * unit(random), r.z * unit(random)};
            if (!s.enclosing_polytope().misses(start, end - start, 1)) continue;
            ++rejected;
            for (int k = 0; k <= 1000; ++k) {
                const double tau = k / 1000.0;
                ASSERT_GT(s.gauge(start + (end - start) * tau), 1) << shape << " " << i << " " << tau;
            }
        }
    }
    EXPECT_GT(rejected, 2000);  // the test tests something: boxy shapes have no planes, stars reject many segments
}

TEST(SuperquadricEnclosingPolytope, AnOctahedronsPlanesAreItsFaces) {
    // ε1 = ε2 = 2: |x|/a + |y|/b + |z|/c ≤ 1 exactly.
    const Superellipsoid octahedron{{1, 2, 3}, 2, 2};
    const EnclosingPolytope& planes = octahedron.enclosing_polytope();
    const Vec3d face_centre{1.0 / 3, 2.0 / 3, 3.0 / 3};
    const Vec3d along_face = normalize(Vec3d{1, -2, 0}) * 0.1;  // x/1 + y/2 stays the same
    EXPECT_TRUE(planes.misses(face_centre * 1.001 - along_face, along_face, 2));
    EXPECT_FALSE(planes.misses(face_centre * 0.999 - along_face, along_face, 2));
    // The ellipsoid through the box's face centres reaches much further.
    EXPECT_TRUE(planes.misses(face_centre * 1.5, Vec3d{0, 0, 1}, 0));
}

}  // namespace
}  // namespace isotrace
