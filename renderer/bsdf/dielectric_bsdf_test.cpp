#include "renderer/bsdf/dielectric_bsdf.h"

#include <gtest/gtest.h>

#include <string>

#include "renderer/bsdf/fresnel.h"
#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

using test_support::direction_from_degrees;

using test_support::kRoughnesses;
using test_support::Roughness;
using test_support::view_at;
// Above 90 degrees wo is inside the glass: 150 (30 from the inward normal) still refracts out, 120 (60) is
// beyond the critical angle of 41.8 degrees for a smooth interface, so both regimes are covered.
const double kViewAngles[] = {0, 30, 60, 85, 150, 120};
constexpr float kEta = 1.5f;
constexpr std::size_t kSamples = 100000;
const double kSignificance = test_support::sidak_significance(0.01, std::size(kRoughnesses) * std::size(kViewAngles));

class RoughDielectricSampling : public testing::TestWithParam<std::tuple<Roughness, double>> {};

TEST_P(RoughDielectricSampling, MatchesPdf) {
    const auto [r, theta] = GetParam();
    const DielectricBsdf bsdf(kEta, r.alpha_x, r.alpha_y);
    const auto fit = test_support::sampling_fit(bsdf, view_at(theta), kSamples);
    EXPECT_GT(fit.chi_square.p_value, kSignificance);
    // Reflections that would go below the horizon and refractions that would stay on wo's side are lost
    // (quadrature tolerance 2e-3).
    EXPECT_LE(fit.pdf_integral, 1.0 + 2e-3);
}

INSTANTIATE_TEST_SUITE_P(RoughnessAndView, RoughDielectricSampling,
                         testing::Combine(testing::ValuesIn(kRoughnesses), testing::ValuesIn(kViewAngles)),
                         test_support::roughness_and_view_name);

TEST(DielectricBsdf, WrongPdfIsRejected) {
    // Proves the test can fail: samples refracted with IOR 1.5 judged against the density for IOR 1.33.
    const DielectricBsdf bsdf(kEta, 0.3f, 0.3f), water(1.33f, 0.3f, 0.3f);
    const Vec3f wo = view_at(30);
    const auto fit = test_support::sampling_fit(bsdf, wo, kSamples, [&](const Vec3f& wi) { return water.pdf(wo, wi); });
    EXPECT_LT(fit.chi_square.p_value, 1e-12);
}

// Random directions on both sides of the surface.
std::pair<Vec3f, Vec3f> random_pair(std::size_t i) {
    const auto r = test_support::bsdf_random(i);
    return {direction_from_degrees(179 * r.u[0] + 0.5, 360 * r.u[1]), direction_from_degrees(179 * r.u_lobe + 0.5, 720 * r.u[0])};
}

float ior_on_side_of(const Vec3f& w) { return w.z > 0 ? 1.0f : kEta; }

TEST(DielectricBsdf, ObeysGeneralisedReciprocity) {
    const DielectricBsdf bsdf(kEta, 0.2f, 0.4f);
    int transmissions = 0;
    for (std::size_t i = 0; i < 2000; ++i) {
        const auto [a, b] = random_pair(i);
        const Rgb ab = bsdf.eval(a, b), ba = bsdf.eval(b, a);
        if (a.z * b.z < 0 && !ab.is_black()) ++transmissions;
        // f(wo, wi) / eta_wo^2 = f(wi, wo) / eta_wi^2 in Radiance mode (plain symmetry for reflection).
        const float lhs = ab.g / (ior_on_side_of(a) * ior_on_side_of(a));
        const float rhs = ba.g / (ior_on_side_of(b) * ior_on_side_of(b));
        EXPECT_NEAR(lhs, rhs, 1e-4f * std::max(lhs, rhs) + 1e-7f) << i;
        // Importance transport is the adjoint.
        EXPECT_NEAR(bsdf.eval(a, b, TransportMode::Importance).g, ba.g, 1e-4f * ba.g + 1e-7f) << i;
    }
    EXPECT_GT(transmissions, 100);
}

TEST(DielectricBsdf, SmoothInterfaceSplitsByFresnel) {
    const DielectricBsdf bsdf(kEta, 0, 0, Rgb(1.0f, 0.5f, 0.25f));
    EXPECT_TRUE(bsdf.has_delta_lobe() && bsdf.is_fully_delta());
    const Vec3f wo = view_at(45);
    const float f = fresnel_dielectric(wo.z, kEta);

    const std::optional<BsdfSample> reflection = bsdf.sample(wo, 0.5f * f, {0.5f, 0.5f});
    ASSERT_TRUE(reflection && reflection->is_delta && !reflection->is_transmission);
    EXPECT_EQ(reflection->wi, Vec3f(-wo.x, -wo.y, wo.z));
    EXPECT_FLOAT_EQ(reflection->pdf, f);
    EXPECT_EQ(reflection->weight, Rgb(1.0f));  // the surface reflection is not tinted

    const std::optional<BsdfSample> refraction = bsdf.sample(wo, 0.5f * (1 + f), {0.5f, 0.5f});
    ASSERT_TRUE(refraction && refraction->is_delta && refraction->is_transmission);
    EXPECT_FLOAT_EQ(refraction->pdf, 1 - f);
    EXPECT_FLOAT_EQ(refraction->eta, kEta);
    // Snell's law: sin(theta_t) = sin(theta_i) / eta, on the far side, in the plane of incidence.
    EXPECT_NEAR(std::sqrt(1 - refraction->wi.z * refraction->wi.z), std::sqrt(1 - wo.z * wo.z) / kEta, 1e-6f);
    EXPECT_LT(refraction->wi.z, 0);
    EXPECT_NEAR(refraction->wi.x * wo.y - refraction->wi.y * wo.x, 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(refraction->weight.g, 0.5f / (kEta * kEta));  // radiance compressed by eta^2
    const std::optional<BsdfSample> importance = bsdf.sample(wo, 0.5f * (1 + f), {0.5f, 0.5f}, TransportMode::Importance);
    EXPECT_FLOAT_EQ(importance->weight.g, 0.5f);
}

TEST(DielectricBsdf, TotalInternalReflectionAlwaysReflects) {
    const DielectricBsdf bsdf(kEta, 0, 0);
    const Vec3f inside = view_at(120);  // 60 degrees from the inward normal, beyond the critical angle
    for (float u : {0.0f, 0.5f, 0.999f}) {
        const std::optional<BsdfSample> s = bsdf.sample(inside, u, {0.5f, 0.5f});
        ASSERT_TRUE(s && !s->is_transmission);
        EXPECT_EQ(s->weight, Rgb(1.0f));
        EXPECT_FLOAT_EQ(s->pdf, 1.0f);
    }
}

TEST(DielectricBsdf, WhiteFurnace) {
    // Importance transport carries no 1/eta^2, so a clear interface conserves it: smooth exactly, rough at
    // most (single scattering loses what bounces between microfacets).
    for (double theta : {0.0, 45.0, 80.0, 170.0, 120.0}) {
        const Vec3f wo = view_at(theta);
        const auto smooth = test_support::estimate_albedo(DielectricBsdf(kEta, 0, 0), wo, 10000, TransportMode::Importance);
        EXPECT_FLOAT_EQ(smooth.mean.g, 1.0f) << theta;
        for (float alpha : {0.05f, 0.3f, 0.8f}) {
            const auto rough =
                test_support::estimate_albedo(DielectricBsdf(kEta, alpha, alpha), wo, 20000, TransportMode::Importance);
            EXPECT_LE(rough.mean.g, 1.0f + 3 * rough.standard_error.g) << theta << " " << alpha;
            EXPECT_GT(rough.mean.g, 0.5f) << theta << " " << alpha;
        }
    }
    // In Radiance mode entering light is compressed: F + (1 - F) / eta^2 from outside.
    const Vec3f wo = view_at(30);
    const float f = fresnel_dielectric(wo.z, kEta);
    EXPECT_NEAR(test_support::estimate_albedo(DielectricBsdf(kEta, 0, 0), wo, 20000).mean.g, f + (1 - f) / (kEta * kEta), 0.01f);
}

TEST(DielectricBsdf, SamplesAreConsistentAndFiniteInExtremeCases) {
    const Vec3f views[] = {Vec3f(0, 0, 1), direction_from_degrees(89.9), direction_from_degrees(90.1), Vec3f(0, 0, -1),
                           view_at(150)};
    for (float alpha : {0.0f, 1e-6f, 1e-3f, 0.3f, 1.0f}) {
        const DielectricBsdf bsdf(kEta, alpha, alpha);
        for (const Vec3f& wo : views) {
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                EXPECT_EQ(test_support::count_bad_samples(bsdf, wo, 2000, mode), 0u) << alpha << " " << wo.z;
            }
        }
    }
}

}  // namespace
}  // namespace isotrace
