#include "renderer/bsdf/charlie_sheen.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

using test_support::direction_from_degrees;

const float kRoughnesses[] = {0.3f, 0.41f, 0.5f, 0.77f, 1.0f};

TEST(CharlieSheen, DistributionsProjectedAreaIsOne) {
    for (float roughness : kRoughnesses) {
        const CharlieSheen sheen(roughness);
        const double area =
            test_support::sphere_integral([&](const Vec3f& m) { return m.z > 0 ? sheen.d(m) * m.z : 0.0; });
        EXPECT_NEAR(area, 1.0, 1e-3) << roughness;
    }
}

TEST(CharlieSheen, IsReciprocal) {
    const CharlieSheen sheen(0.4f);
    for (std::size_t i = 0; i < 500; ++i) {
        const auto r = test_support::bsdf_random(i);
        const Vec3f a = direction_from_degrees(89.9 * r.u[0], 360 * r.u[1]);
        const Vec3f b = direction_from_degrees(89.9 * r.u_lobe, 360 * r.u[0]);
        const float ab = sheen.eval(a, b), ba = sheen.eval(b, a);
        EXPECT_NEAR(ab, ba, 1e-5f * ab);
    }
}

TEST(CharlieSheen, AlbedoTableMatchesQuadrature) {
    // Within 2e-3 between the table's nodes, up to 88 degrees; at most 1, so that the sheen creates no energy and a
    // layer under it keeps a non-negative share.
    for (float roughness : kRoughnesses) {
        const CharlieSheen sheen(roughness);
        for (double theta : {0.0, 30.0, 60.0, 80.0, 88.0}) {
            const Vec3f wo = direction_from_degrees(theta, 20);
            const double albedo = test_support::sphere_integral(
                [&](const Vec3f& wi) { return wi.z > 0 ? sheen.eval(wo, wi) * wi.z : 0.0; });
            EXPECT_NEAR(sheen.albedo(wo.z), albedo, 2e-3) << roughness << " " << theta;
            EXPECT_LE(sheen.albedo(wo.z), 1.0f);
        }
    }
}

TEST(CharlieSheen, AlbedoNeverExceedsOne) {
    // Down to the smallest roughness (below it the roughness is raised) and at every view.
    for (float roughness : {0.0f, kMinSheenRoughness, 0.35f, 0.6f, 1.0f}) {
        const CharlieSheen sheen(roughness);
        for (int i = 0; i <= 1000; ++i) EXPECT_LE(sheen.albedo(i / 1000.0f), 1.0f) << roughness << " " << i;
    }
}

}  // namespace
// A unit vector carried into the shading frame can come out with z a rounding above 1: the masking fit read
// 1 - z there, and its power of a negative number made a NaN sample in a render.
TEST(CharlieSheen, CosinesARoundingAboveOneStayFinite) {
    const CharlieSheen sheen(0.5f);
    const float above_one = std::nextafter(1.0f, 2.0f);
    EXPECT_TRUE(std::isfinite(sheen.lambda(above_one)));
    EXPECT_NEAR(sheen.lambda(above_one), sheen.lambda(1.0f), 1e-6f);
    const Vec3f up(0, 0, above_one), tilted = normalize(Vec3f(0.3f, 0.2f, 0.9f));
    EXPECT_TRUE(std::isfinite(sheen.eval(up, tilted)));
    EXPECT_TRUE(std::isfinite(sheen.eval(tilted, up)));
}

}  // namespace isotrace
