#include "renderer/bsdf/conductor_bsdf.h"

#include <gtest/gtest.h>

#include <string>

#include "renderer/bsdf/conductor_presets.h"
#include "renderer/sampling/warps.h"
#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

using test_support::direction_from_degrees;

using test_support::kRoughnesses;
using test_support::Roughness;
using test_support::view_at;
const double kViewAngles[] = {0, 30, 60, 85};
constexpr std::size_t kSamples = 100000;
const double kSignificance = test_support::sidak_significance(0.01, std::size(kRoughnesses) * std::size(kViewAngles));
const ComplexIor kGold = *find_conductor_preset("Au");
const ComplexIor kPerfectMirror{Rgb(1.0f), Rgb(1e4f)};  // k -> infinity: F -> 1 at every angle

class RoughConductorSampling : public testing::TestWithParam<std::tuple<Roughness, double>> {};

TEST_P(RoughConductorSampling, MatchesPdf) {
    const auto [r, theta] = GetParam();
    const ConductorBsdf bsdf(kGold, r.alpha_x, r.alpha_y);
    const auto fit = test_support::sampling_fit(bsdf, view_at(theta), kSamples);
    EXPECT_GT(fit.chi_square.p_value, kSignificance);
    // Reflections of wo that would go below the horizon are lost, never gained (quadrature tolerance 2e-3).
    EXPECT_LE(fit.pdf_integral, 1.0 + 2e-3);
}

INSTANTIATE_TEST_SUITE_P(RoughnessAndView, RoughConductorSampling,
                         testing::Combine(testing::ValuesIn(kRoughnesses), testing::ValuesIn(kViewAngles)),
                         test_support::roughness_and_view_name);

TEST(ConductorBsdf, PdfMassIsTheShareReflectedAboveTheHorizon) {
    // At normal incidence the visible normals are distributed as D(m) m.z, whose share with tan^2(theta_m) <= t
    // is t / (t + alpha^2); wi stays above the horizon exactly when theta_m < 45 degrees (t = 1).
    for (float alpha : {0.05f, 0.3f, 0.8f}) {
        const ConductorBsdf bsdf(kGold, alpha, alpha);
        EXPECT_NEAR(test_support::pdf_integral(bsdf, Vec3f(0, 0, 1)), 1 / (1 + alpha * alpha), 1e-3) << alpha;
    }
}

TEST(ConductorBsdf, WrongPdfIsRejected) {
    // Proves the test can fail: GGX samples judged against the cosine-hemisphere density.
    const ConductorBsdf bsdf(kGold, 0.3f, 0.3f);
    const auto fit = test_support::sampling_fit(bsdf, view_at(30), kSamples,
                                                [](const Vec3f& wi) { return square_to_cosine_hemisphere_pdf(wi); });
    EXPECT_LT(fit.chi_square.p_value, 1e-12);
}

TEST(ConductorBsdf, IsReciprocal) {
    const ConductorBsdf bsdf(kGold, 0.2f, 0.5f);
    for (std::size_t i = 0; i < 1000; ++i) {
        const auto r = test_support::bsdf_random(i);
        const Vec3f a = direction_from_degrees(89 * r.u[0], 360 * r.u[1]);
        const Vec3f b = direction_from_degrees(89 * r.u_lobe, 360 * r.u[0]);
        const Rgb ab = bsdf.eval(a, b), ba = bsdf.eval(b, a);
        EXPECT_NEAR(ab.r, ba.r, 1e-5f * ab.r + 1e-7f);
        EXPECT_NEAR(ab.b, ba.b, 1e-5f * ab.b + 1e-7f);
    }
}

TEST(ConductorBsdf, SmoothMirrorReflectsTheFresnelShare) {
    const ConductorBsdf bsdf(kGold, 0, 0);
    EXPECT_TRUE(bsdf.has_delta_lobe() && bsdf.is_fully_delta());
    const Vec3f wo = view_at(60);
    const std::optional<BsdfSample> s = bsdf.sample(wo, 0.5f, {0.5f, 0.5f});
    ASSERT_TRUE(s && s->is_delta);
    EXPECT_EQ(s->wi, Vec3f(-wo.x, -wo.y, wo.z));
    EXPECT_EQ(s->weight, fresnel_conductor(wo.z, kGold));
    EXPECT_TRUE(bsdf.eval(wo, s->wi).is_black());
    EXPECT_EQ(bsdf.pdf(wo, s->wi), 0.0f);
    // From below, the mirror is on wo's side.
    EXPECT_EQ(bsdf.sample(-wo, 0.5f, {0.5f, 0.5f})->wi, Vec3f(wo.x, wo.y, -wo.z));
}

TEST(ConductorBsdf, WhiteFurnace) {
    for (double theta : {0.0, 45.0, 80.0}) {
        const Vec3f wo = view_at(theta);
        const auto smooth = test_support::estimate_albedo(ConductorBsdf(kPerfectMirror, 0, 0), wo, 100);
        EXPECT_FLOAT_EQ(smooth.mean.r, fresnel_conductor(wo.z, kPerfectMirror).r);
        EXPECT_GT(smooth.mean.r, 0.999f);
        for (float alpha : {0.05f, 0.3f, 0.8f}) {
            // Single scattering loses what bounces between microfacets: the albedo is at most one.
            const auto rough = test_support::estimate_albedo(ConductorBsdf(kPerfectMirror, alpha, alpha), wo, 20000);
            EXPECT_LE(rough.mean.r, 1.0f + 3 * rough.standard_error.r) << theta << " " << alpha;
            EXPECT_GT(rough.mean.r, 0.3f) << theta << " " << alpha;  // ~0.43 at 80 degrees and alpha 0.8
        }
    }
}

TEST(ConductorBsdf, SamplesAreConsistentAndFiniteInExtremeCases) {
    for (float alpha : {1e-6f, 1e-3f, 0.3f, 1.0f}) {
        const ConductorBsdf bsdf(kGold, alpha, alpha);
        for (const Vec3f& wo : {Vec3f(0, 0, 1), direction_from_degrees(89.9), direction_from_degrees(120, 10)}) {
            EXPECT_EQ(test_support::count_bad_samples(bsdf, wo, 2000), 0u) << alpha << " " << wo.z;
        }
    }
}

}  // namespace
}  // namespace isotrace
