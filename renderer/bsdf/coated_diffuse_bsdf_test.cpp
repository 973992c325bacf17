#include "renderer/bsdf/coated_diffuse_bsdf.h"

#include <gtest/gtest.h>

#include <string>

#include "renderer/bsdf/fresnel.h"
#include "renderer/sampling/warps.h"
#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

using test_support::direction_from_degrees;

const float kAlphas[] = {0.0f, 0.05f, 0.3f, 0.8f};  // 0: smooth coating, a delta lobe plus the diffuse base
const double kViewAngles[] = {0, 30, 60, 85};
constexpr float kEta = 1.5f;
constexpr std::size_t kSamples = 100000;
const double kSignificance = test_support::sidak_significance(0.01, std::size(kAlphas) * std::size(kViewAngles));

using test_support::view_at;

std::string test_name(const testing::TestParamInfo<std::tuple<float, double>>& info) {
    const auto& [alpha, theta] = info.param;
    return "alpha" + std::to_string(int(alpha * 100)) + "_theta" + std::to_string(int(theta));
}

class CoatedDiffuseSampling : public testing::TestWithParam<std::tuple<float, double>> {};

TEST_P(CoatedDiffuseSampling, MatchesPdf) {
    const auto [alpha, theta] = GetParam();
    const DielectricCoating coating(kEta, alpha);
    const CoatedDiffuseBsdf bsdf(coating, Rgb(0.2f, 0.5f, 0.8f));
    // Delta samples of the smooth coating fall outside the grid, where the pdf leaves exactly their share.
    const auto fit = test_support::sampling_fit(bsdf, view_at(theta), kSamples);
    EXPECT_GT(fit.chi_square.p_value, kSignificance);
    EXPECT_LE(fit.pdf_integral, 1.0 + 2e-3);
}

INSTANTIATE_TEST_SUITE_P(RoughnessAndView, CoatedDiffuseSampling,
                         testing::Combine(testing::ValuesIn(kAlphas), testing::ValuesIn(kViewAngles)), test_name);

TEST(CoatedDiffuseBsdf, WrongPdfIsRejected) {
    // Proves the test can fail: the mixture's samples judged against its diffuse component alone.
    const DielectricCoating coating(kEta, 0.3f);
    const CoatedDiffuseBsdf bsdf(coating, Rgb(0.5f));
    const auto fit = test_support::sampling_fit(bsdf, view_at(30), kSamples,
                                                [](const Vec3f& wi) { return square_to_cosine_hemisphere_pdf(wi); });
    EXPECT_LT(fit.chi_square.p_value, 1e-12);
}

TEST(CoatedDiffuseBsdf, IsReciprocal) {
    for (float alpha : kAlphas) {
        const DielectricCoating coating(kEta, alpha);
        const CoatedDiffuseBsdf bsdf(coating, Rgb(0.9f));
        for (std::size_t i = 0; i < 500; ++i) {
            const auto r = test_support::bsdf_random(i);
            const Vec3f a = direction_from_degrees(89 * r.u[0], 360 * r.u[1]);
            const Vec3f b = direction_from_degrees(89 * r.u_lobe, 360 * r.u[0]);
            const float ab = bsdf.eval(a, b).g, ba = bsdf.eval(b, a).g;
            EXPECT_NEAR(ab, ba, 1e-5f * ab) << alpha;
        }
    }
}

TEST(CoatedDiffuseBsdf, ConservesEnergyForEveryView) {
    // Albedo <= 1 for every wo (within 4 standard errors and the table's 1e-3); a white base under a smooth
    // coating loses nothing, so its albedo is exactly 1.
    for (float alpha : kAlphas) {
        const DielectricCoating coating(kEta, alpha);
        const CoatedDiffuseBsdf white(coating, Rgb(1.0f));
        for (double theta : {0.0, 20.0, 40.0, 60.0, 75.0, 85.0, 89.0, 89.9}) {
            const auto albedo = test_support::estimate_albedo(white, view_at(theta), 20000);
            EXPECT_LE(albedo.mean.g, 1.0f + 4 * albedo.standard_error.g + 1e-3f) << alpha << " " << theta;
            if (alpha == 0) {
                EXPECT_NEAR(albedo.mean.g, 1.0f, 4 * albedo.standard_error.g + 1e-4f) << theta;
            }
        }
    }
}

TEST(CoatedDiffuseBsdf, SmoothCoatingMirrorCarriesTheFresnelShare) {
    const DielectricCoating coating(kEta, 0);
    const CoatedDiffuseBsdf bsdf(coating, Rgb(0.5f));
    EXPECT_TRUE(bsdf.has_delta_lobe());
    EXPECT_FALSE(bsdf.is_fully_delta());
    const Vec3f wo = view_at(60);
    const std::optional<BsdfSample> mirror = bsdf.sample(wo, 0.0f, {0.5f, 0.5f});
    ASSERT_TRUE(mirror && mirror->is_delta);
    EXPECT_EQ(mirror->wi, Vec3f(-wo.x, -wo.y, wo.z));
    EXPECT_NEAR(mirror->weight.g * mirror->pdf, fresnel_dielectric(wo.z, kEta), 1e-6f);
}

TEST(CoatedDiffuseBsdf, SamplesAreConsistentAndFiniteInExtremeCases) {
    for (float alpha : {0.0f, 1e-6f, 1e-3f, 0.3f, 1.0f}) {
        const DielectricCoating coating(kEta, alpha);
        const CoatedDiffuseBsdf bsdf(coating, Rgb(0.5f));
        for (const Vec3f& wo : {Vec3f(0, 0, 1), direction_from_degrees(89.9), direction_from_degrees(120, 10)}) {
            EXPECT_EQ(test_support::count_bad_samples(bsdf, wo, 2000), 0u) << alpha << " " << wo.z;
        }
    }
}

}  // namespace
}  // namespace isotrace
