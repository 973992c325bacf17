// The part of a segment within a bend's annular sector, against points of bent objects and the sector's own
// inequalities sampled along the segment.
#include "geometry/superquadric/bend_sector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/superquadric/deformation_chain.h"

namespace isotrace {
namespace {

// Whether p lies in the sector (its scaled radius between inner and outer, its angle between the lowest and the
// highest cross-section's).
bool in_sector(const BendSector& sector, const Vec3d& p) {
    const double a = sector.curvature * dot(p, sector.toward) - 1, b = sector.curvature * (p.z - sector.centre);
    const double r = std::hypot(a, b);
    return r >= sector.inner && r <= sector.outer && a * sector.sin_lo + b * sector.cos_lo >= 0 &&
           a * sector.sin_hi + b * sector.cos_hi <= 0;
}

// Bent random superellipsoids, twisted or tapered first or not: every point of the bent solid lies in the chain's
// sector, and a segment through such a point keeps it in its stretch.
TEST(SuperquadricBendSector, HoldsTheBentSolidAndTheStretchHoldsItsPoints) {
    std::mt19937 random(23);
    std::uniform_real_distribution<double> unit(-1, 1), exponent(0.1, 3), size(0.3, 1.2);
    int points = 0, trimmed = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3d radii{size(random), size(random), size(random)};
        const Superellipsoid shape{radii, exponent(random), exponent(random)};
        DeformationChain chain(shape);
        if (i % 3 == 1) chain.append(Twist(2 * unit(random), radii.z));
        if (i % 3 == 2) chain.append(Taper(0.5 * unit(random), 0.5 * unit(random), radii.z));
        const double reach = 1.6 * std::max(radii.x, radii.y);
        chain.append(Bend((0.2 + 0.7 * std::abs(unit(random))) / reach, 3.14159 * unit(random), 0.3 * radii.z * unit(random),
                          chain.deformed_box().z));
        ASSERT_TRUE(chain.enclosing_sector()) << i;
        const BendSector& sector = *chain.enclosing_sector();
        for (int k = 0; k < 100; ++k) {
            Vec3d p;
            do p = {radii.x * unit(random), radii.y * unit(random), radii.z * unit(random)};
            while (shape.gauge(p) > 1);
            const Vec3d q = chain.forward(p);
            ++points;
            EXPECT_TRUE(in_sector(sector, q)) << i << " " << k;
            // A segment from outside the box through q.
            const Vec3d direction = normalize(Vec3d{unit(random), unit(random), unit(random)});
            const Vec3d start = q - direction * 5.0;
            const std::optional<Interval> stretch = sector.stretch(start, direction, 10);
            ASSERT_TRUE(stretch) << i << " " << k;
            EXPECT_TRUE(stretch->contains(5)) << i << " " << k;
            // Where the stretch ends inside the segment the point lies outside the sector.
            for (const double at : {stretch->lo, stretch->hi}) {
                if (at == 0 || at == 10) continue;
                ++trimmed;
                EXPECT_FALSE(in_sector(sector, start + direction * at)) << i << " " << k;
            }
        }
    }
    EXPECT_EQ(points, 30000);
    EXPECT_GT(trimmed, 30000);
}

// A ray through the hole inside the sector, or beside its outer cylinder, or past the lowest cross-section's angle,
// misses it.
TEST(SuperquadricBendSector, RaysThroughTheHoleOrBesideItMissIt) {
    // k = 1 about the centre (1, 0, 0) in the x–z plane: radii (scaled) 0.5 to 1.5, angles ±0.5.
    const BendSector sector{{1, 0, 0}, 1, 0, 0.5, 1.5, std::sin(-0.5), std::cos(-0.5), std::sin(0.5), std::cos(0.5)};
    EXPECT_FALSE(sector.stretch({0.8, -5, 0}, {0, 1, 0}, 10));   // along y through the hole, 0.2 from the centre
    EXPECT_FALSE(sector.stretch({-0.6, -5, 0}, {0, 1, 0}, 10));  // beyond the outer radius
    EXPECT_TRUE(sector.stretch({0, -5, 0}, {0, 1, 0}, 10));      // through the middle of the arc
    // Along z at x = 0: from the centre's side the angle passes ±0.5 where z = ±tan(0.5).
    const std::optional<Interval> chord = sector.stretch({0, 0, -3}, {0, 0, 1}, 6);
    ASSERT_TRUE(chord);
    EXPECT_NEAR(chord->lo, 3 - std::tan(0.5), 1e-6);
    EXPECT_NEAR(chord->hi, 3 + std::tan(0.5), 1e-6);
}

}  // namespace
}  // namespace isotrace
