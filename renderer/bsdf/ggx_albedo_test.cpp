#include "renderer/bsdf/ggx_albedo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "renderer/bsdf/fresnel.h"
#include "renderer/bsdf/ggx.h"
#include "renderer/bsdf/shading_frame.h"
#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

using test_support::direction_from_degrees;

// Off the table's nodes, where interpolation errs most.
const float kRoughnesses[] = {0.02f, 0.1f, 0.3f, 0.55f, 0.9f, 1.0f};

// Monte Carlo albedo: F G2 / G1(wo) averaged over the normals visible from wo (Heitz 2018), with its standard error.
std::pair<double, double> monte_carlo_albedo(const GgxDistribution& ggx, const Vec3f& wo, float f0) {
    constexpr std::size_t n = 100000;
    double sum = 0, sum2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3f m = ggx.sample_visible_normal(wo, test_support::bsdf_random(i).u);
        const Vec3f wi = reflect(wo, m);
        if (wi.z <= 0) continue;
        const double value = fresnel_schlick(dot(wo, m), f0) * ggx.g2(wo, wi) / ggx.g1(wo);
        sum += value;
        sum2 += value * value;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

TEST(GgxAlbedo, SmoothIsSchlicksReflectance) {
    const GgxAlbedo smooth(0, 0);
    EXPECT_EQ(GgxAlbedo(0, 1).albedo(direction_from_degrees(60, 30), 0.04f), fresnel_schlick(0.5f, 0.04f));
    for (float f0 : {0.0f, 0.04f, 0.5f, 1.0f}) {
        for (float mu : {0.0f, 0.02f, 0.3f, 1.0f}) {
            EXPECT_EQ(smooth.albedo(mu, f0), fresnel_schlick(mu, f0)) << f0 << " " << mu;
        }
        EXPECT_NEAR(smooth.average(f0), f0 + (1 - f0) / 21, 2e-4f) << f0;
    }
}

TEST(GgxAlbedo, AgreesWithMonteCarlo) {
    // Within 3e-3 from the normal to 84 degrees; nearer grazing the quadrature and the interpolation between the
    // grid's sparse nodes there err more: 2e-2 at 89 degrees.
    for (float roughness : kRoughnesses) {
        for (float mu : {1.0f, 0.8f, 0.45f, 0.25f, 0.1f, 0.0175f}) {
            for (float f0 : {0.04f, 1.0f}) {
                const float alpha = roughness * roughness;
                const Vec3f wo(std::sqrt(1 - mu * mu), 0, mu);
                const auto [mean, error] = monte_carlo_albedo(GgxDistribution(alpha, alpha), wo, f0);
                const double tolerance = 4 * error + (mu >= 0.1f ? 3e-3 : 2e-2);
                EXPECT_NEAR(GgxAlbedo(roughness, 0).albedo(mu, f0), mean, tolerance)
                    << roughness << " " << mu << " " << f0;
            }
        }
    }
}

TEST(GgxAlbedo, AnisotropicErrsTowardsReflectingMore) {
    // Never more than 0.03 below the true albedo (what lies beneath receives at most that much too much; 0.016
    // seen), at most 0.75 above (light lost; 0.71 seen for the most anisotropic rough lobe).
    for (const auto& [roughness, anisotropy] : {std::pair{0.2f, 0.5f}, {0.2f, 1.0f}, {0.7f, 0.5f}, {1.0f, 1.0f}}) {
        const GgxAlbedo albedo(roughness, anisotropy);
        const auto [alpha_x, alpha_y] = anisotropic_alphas(roughness, anisotropy);
        const GgxDistribution ggx(alpha_x, alpha_y);
        for (double theta : {0.0, 40.0, 60.0, 80.0, 89.0}) {
            for (double phi : {0.0, 30.0, 60.0, 90.0}) {
                const Vec3f wo = direction_from_degrees(theta, phi);
                for (float f0 : {0.04f, 1.0f}) {
                    const auto [mean, error] = monte_carlo_albedo(ggx, wo, f0);
                    const float e = albedo.albedo(wo, f0);
                    const std::string where = std::to_string(roughness) + " " + std::to_string(anisotropy) + " " +
                                              std::to_string(theta) + " " + std::to_string(phi) + " " +
                                              std::to_string(f0);
                    EXPECT_GT(e, mean - 4 * error - 0.03) << where;
                    EXPECT_LT(e, mean + 0.75) << where;
                }
            }
        }
    }
}

TEST(GgxAlbedo, AverageIsTheCosineWeightedMeanOfTheAlbedo) {
    // Anisotropic, between the table's nodes: 6e-3.
    for (const auto& [roughness, anisotropy] : {std::pair{0.43f, 0.3f}, {1.0f, 1.0f}, {0.6f, 0.93f}}) {
        const GgxAlbedo albedo(roughness, anisotropy);
        for (float f0 : {0.04f, 1.0f}) {
            const double average = test_support::sphere_integral([&](const Vec3f& w) {
                return w.z > 0 ? albedo.albedo(w, f0) * w.z / std::numbers::pi : 0.0;
            });
            EXPECT_NEAR(albedo.average(f0), average, 6e-3) << roughness << " " << anisotropy << " " << f0;
        }
    }

    for (float f0 : {0.04f, 0.3f, 1.0f}) {
        for (float roughness : kRoughnesses) {
            const GgxAlbedo albedo(roughness, 0);
            // 2 * integral of E(mu) mu dmu, midpoint rule.
            constexpr int n = 20000;
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                const double mu = (i + 0.5) / n;
                sum += 2 * mu * albedo.albedo(float(mu), f0) / n;
            }
            EXPECT_NEAR(albedo.average(f0), sum, 2e-5) << f0 << " " << roughness;
        }
    }
}

}  // namespace
}  // namespace isotrace
