// The part of a segment inside a cone about z, against the cone's inequality sampled along the segment.
#include "geometry/superquadric/cone_about_z.h"

#include <gtest/gtest.h>

#include <random>

namespace isotrace {
namespace {

// (kx·x)² + (ky·y)² − (α + β·z)² at p: at most 0 inside.
double excess(const ConeAboutZ& cone, const Vec3d& p) {
    const double x = cone.kx * p.x, y = cone.ky * p.y, w = cone.radius_scale(p.z);
    return x * x + y * y - w * w;
}

// Random cones, narrowing or widening (β of either sign) and cylinders, and segments within z ∈ [−1, 1], where
// α + β·z > 0; steep segments cross the cone's side twice or along a generator.
TEST(SuperquadricConeAboutZ, TheStretchIsThePartOfTheSegmentInsideTheCone) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.3, 2);
    int inside = 0, outside = 0, trimmed = 0;
    for (int i = 0; i < 4000; ++i) {
        const double alpha = positive(random), beta = i % 4 == 0 ? 0 : 0.9 * alpha * unit(random);
        const ConeAboutZ cone{positive(random), positive(random), alpha, beta};
        const Vec3d start{2 * unit(random), 2 * unit(random), unit(random)}, end{2 * unit(random), 2 * unit(random),
                                                                               unit(random)};
        const Vec3d direction = normalize(end - start);
        const double length = isotrace::length(end - start);
        const std::optional<Interval> stretch = cone.stretch(start, direction, length);
        for (int k = 0; k <= 400; ++k) {
            const double t = k == 400 ? length : length * k / 400;
            const double e = excess(cone, start + direction * t);
            if (e <= 0) {
                ++inside;
                ASSERT_TRUE(stretch) << i;
                EXPECT_TRUE(stretch->contains(t)) << i << " t " << t;
            } else if (e > 1e-6 && stretch && stretch->contains(t)) {
                ++outside;
            }
        }
        if (!stretch) continue;
        // Where the stretch ends inside the segment, the point lies outside the cone, by its margin.
        for (const double at : {stretch->lo, stretch->hi}) {
            if (at == 0 || at == length) continue;
            ++trimmed;
            EXPECT_GT(excess(cone, start + direction * at), 0) << i;
        }
    }
    EXPECT_GT(inside, 100000);
    EXPECT_GT(trimmed, 1000);
    EXPECT_EQ(outside, 0);  // one interval: no sample well outside lies between its ends
}

TEST(SuperquadricConeAboutZ, AlongTheAxisAndBesideAnUprightCone) {
    // Radius 1 + z/2 about z: 0.5 at z = −1, 1.5 at z = 1.
    const ConeAboutZ cone{1, 1, 1, 0.5};
    const std::optional<Interval> axis = cone.stretch({0, 0, -1}, {0, 0, 1}, 2);
    ASSERT_TRUE(axis);
    EXPECT_EQ(axis->lo, 0);
    EXPECT_EQ(axis->hi, 2);
    // At height 0.6 the radius is 1.3: along x the chord is x in [−1.3, 1.3].
    const std::optional<Interval> chord = cone.stretch({-2, 0, 0.6}, {1, 0, 0}, 4);
    ASSERT_TRUE(chord);
    EXPECT_NEAR(chord->lo, 0.7, 1e-7);
    EXPECT_NEAR(chord->hi, 3.3, 1e-7);
    // Along the side x = 1 + z/2, just outside it and just inside.
    const Vec3d side = normalize(Vec3d{0.5, 0, 1});
    EXPECT_FALSE(cone.stretch({0.5 + 1e-4, 0, -1}, side, 2));
    EXPECT_TRUE(cone.stretch({0.5 - 1e-4, 0, -1}, side, 2));
}

}  // namespace
}  // namespace isotrace
