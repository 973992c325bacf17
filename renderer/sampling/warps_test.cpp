#include "renderer/sampling/warps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "renderer/sampling/independent_sampler.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

using test_support::Grid2D;
using test_support::Point2;

constexpr double kPi = std::numbers::pi;
constexpr std::size_t kSamples = 400000;
constexpr int kWarpTests = 5;  // one chi-square test per warp
const double kSignificance = test_support::sidak_significance(0.01, kWarpTests);

// Independent (not stratified) inputs: the chi-square test assumes independent samples.
std::array<float, 2> square_sample(std::size_t i) {
    static const IndependentSampler sampler(2024);
    const PixelSampleKey key{static_cast<uint32_t>(i), 0, 0};
    return {sampler.sample(key, 0), sampler.sample(key, 1)};
}

// Directions are histogrammed over (cos theta, phi) in [-1,1] x [0,2pi): that map preserves area, so the
// density there equals the density per solid angle, and any direction below the horizon lands in cells
// a hemisphere density gives no mass.
const Grid2D kSphereGrid{-1, 1, 0, 2 * kPi, 20, 40};

Point2 to_cos_theta_phi(const Vec3f& w) {
    const double phi = std::atan2(double(w.y), double(w.x));
    return {w.z, phi < 0 ? phi + 2 * kPi : phi};
}

Vec3f from_cos_theta_phi(double z, double phi) {
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    return Vec3f(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
}

double direction_warp_p_value(const std::function<Vec3f(std::array<float, 2>)>& warp,
                              const std::function<double(const Vec3f&)>& pdf) {
    return test_support::chi_square_test_2d(
               kSphereGrid, kSamples, [&](std::size_t i) { return to_cos_theta_phi(warp(square_sample(i))); },
               [&](double z, double phi) { return pdf(from_cos_theta_phi(z, phi)); })
        .p_value;
}

TEST(Warps, UniformSphereMatchesPdf) {
    EXPECT_GT(direction_warp_p_value(square_to_uniform_sphere, [](const Vec3f&) { return square_to_uniform_sphere_pdf(); }),
              kSignificance);
}

TEST(Warps, CosineHemisphereMatchesPdf) {
    EXPECT_GT(direction_warp_p_value(square_to_cosine_hemisphere, square_to_cosine_hemisphere_pdf), kSignificance);
}

TEST(Warps, WrongPdfIsRejected) {
    // Proves the warp tests can fail: cosine-distributed samples judged against the uniform hemisphere density.
    const auto uniform_hemisphere = [](const Vec3f& w) { return w.z >= 0 ? 1 / (2 * kPi) : 0.0; };
    EXPECT_LT(direction_warp_p_value(square_to_cosine_hemisphere, uniform_hemisphere), 1e-12);
    // A subtler error: a cosine-power-like density that is only slightly off (cos^1.1 normalised).
    const auto slightly_wrong = [](const Vec3f& w) { return w.z > 0 ? 2.1 / (2 * kPi) * std::pow(w.z, 1.1) : 0.0; };
    EXPECT_LT(direction_warp_p_value(square_to_cosine_hemisphere, slightly_wrong), 1e-6);
}

TEST(Warps, ConcentricDiskMatchesPdf) {
    const Grid2D grid{-1, 1, -1, 1, 24, 24};
    const auto point = [](std::size_t i) {
        const auto [x, y] = square_to_uniform_disk_concentric(square_sample(i));
        return Point2{x, y};
    };
    const auto density = [](double x, double y) { return x * x + y * y < 1 ? 1 / kPi : 0.0; };
    EXPECT_GT(test_support::chi_square_test_2d(grid, kSamples, point, density).p_value, kSignificance);
}

// The map's one division is by the larger coordinate: at the centre, where both are 0, the point is the centre.
TEST(Warps, ConcentricDiskMapsTheCentreToTheCentre) {
    const auto [x, y] = square_to_uniform_disk_concentric({0.5f, 0.5f});
    EXPECT_EQ(x, 0.0f);
    EXPECT_EQ(y, 0.0f);
}

TEST(Warps, TriangleMatchesPdf) {
    const Grid2D grid{0, 1, 0, 1, 24, 24};
    const auto point = [](std::size_t i) {
        const auto [b0, b1] = square_to_uniform_triangle(square_sample(i));
        return Point2{b0, b1};
    };
    const auto density = [](double b0, double b1) { return b0 + b1 < 1 ? 2.0 : 0.0; };
    EXPECT_GT(test_support::chi_square_test_2d(grid, kSamples, point, density).p_value, kSignificance);
}

TEST(Warps, DirectionsAreUnitLengthOnTheRightSide) {
    const float edge = 1.0f - 0x1p-24f;
    for (std::array<float, 2> u : {std::array<float, 2>{0, 0}, {edge, edge}, {0, edge}, {edge, 0}, {0.5f, 0.5f}, {0.3f, 0.9f}}) {
        for (const Vec3f& w : {square_to_uniform_sphere(u), square_to_cosine_hemisphere(u)}) {
            EXPECT_NEAR(length(w), 1.0f, 1e-6f);
        }
        EXPECT_GE(square_to_cosine_hemisphere(u).z, 0.0f);
        const auto [x, y] = square_to_uniform_disk_concentric(u);
        EXPECT_LE(x * x + y * y, 1.0f + 1e-6f);
        const auto [b0, b1] = square_to_uniform_triangle(u);
        EXPECT_GE(b0, 0.0f);
        EXPECT_GE(b1, 0.0f);
        EXPECT_LE(b0 + b1, 1.0f);
    }
}

TEST(Warps, PdfsVanishBelowTheHorizon) {
    EXPECT_EQ(square_to_cosine_hemisphere_pdf({0, 0, -1}), 0.0f);
    EXPECT_FLOAT_EQ(square_to_cosine_hemisphere_pdf({0, 0, 1}), float(1 / kPi));
}

}  // namespace
}  // namespace isotrace
