// SphericalRectangle (Ureña, Fajardo and King): the solid angle against the closed form, samples on the rectangle
// distributed uniformly by solid angle (chi-square against cos θ / (d² Ω) over the rectangle), references on
// either side, and the cases it declines (in the plane, too small an angle).
#include "geometry/rectangle/spherical_rectangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "renderer/sampling/independent_sampler.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

// The solid angle of a 2a × 2b rectangle seen from distance h on its centre's normal.
double centred_solid_angle(double a, double b, double h) {
    return 4 * std::asin(a * b / std::sqrt((a * a + h * h) * (b * b + h * h)));
}

TEST(SphericalRectangle, SolidAngleMatchesTheClosedForm) {
    for (const double h : {0.01, 0.5, 2.0, 30.0}) {
        const auto r = SphericalRectangle::make({0, 0, h}, {-1, -0.5, 0}, {2, 0, 0}, {0, 1, 0});
        ASSERT_TRUE(r) << h;
        EXPECT_NEAR(r->solid_angle(), centred_solid_angle(1, 0.5, h), 1e-12) << h;
        const auto below = SphericalRectangle::make({0, 0, -h}, {-1, -0.5, 0}, {2, 0, 0}, {0, 1, 0});
        ASSERT_TRUE(below) << h;
        EXPECT_NEAR(below->solid_angle(), r->solid_angle(), 1e-12) << h;
    }
    EXPECT_FALSE(SphericalRectangle::make({3, 0, 0}, {-1, -0.5, 0}, {2, 0, 0}, {0, 1, 0}));    // in the plane
    EXPECT_FALSE(SphericalRectangle::make({0, 0, 200}, {-1, -0.5, 0}, {2, 0, 0}, {0, 1, 0}));  // 5e-5 sr
}

// Samples of the rectangle corner + x·(w, 0, 0) + y·(0, hgt, 0) seen from `reference`, chi-square tested.
void expect_uniform_by_solid_angle(const Vec3d& reference, double w, double hgt) {
    const Vec3d corner(-0.3, -0.2, 0);
    const auto r = SphericalRectangle::make(reference, corner, {w, 0, 0}, {0, hgt, 0});
    ASSERT_TRUE(r);
    const IndependentSampler sampler(17);
    constexpr std::uint32_t samples = 100000;
    std::vector<test_support::Point2> points;
    for (std::uint32_t i = 0; i < samples; ++i) {
        const auto xy = r->sample({sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)});
        ASSERT_TRUE(xy[0] >= 0 && xy[0] <= 1 && xy[1] >= 0 && xy[1] <= 1) << xy[0] << " " << xy[1];
        points.push_back({xy[0], xy[1]});
    }
    // Uniform by solid angle: density per unit (x, y) = |z| / d³ · w·hgt / Ω.
    const double omega = r->solid_angle();
    const auto density = [&](double x, double y) {
        const Vec3d p = corner + Vec3d(x * w, y * hgt, 0) - reference;
        const double d = length(p);
        return std::abs(reference.z) / (d * d * d) * w * hgt / omega;
    };
    const test_support::Grid2D grid{0, 1, 0, 1, 10, 10};
    const auto result = test_support::chi_square_test_2d(grid, points.size(), [&](std::size_t i) { return points[i]; }, density);
    EXPECT_GT(result.p_value, 0.01) << "statistic " << result.statistic << ", reference " << reference.x << " "
                                    << reference.y << " " << reference.z;
}

TEST(SphericalRectangle, SamplesAreUniformBySolidAngle) {
    expect_uniform_by_solid_angle({0, 0, 0.3}, 1, 0.6);     // close above: strongly non-uniform by area
    expect_uniform_by_solid_angle({2, -1, -0.8}, 1, 0.6);   // off to the side, below
    expect_uniform_by_solid_angle({0.1, 0.1, 0.02}, 1, 0.6);  // nearly touching
    expect_uniform_by_solid_angle({0, 0, 20}, 2, 1);        // a small angle, 5e-3 sr
}

}  // namespace
}  // namespace isotrace
