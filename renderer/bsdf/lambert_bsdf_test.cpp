#include "renderer/bsdf/lambert_bsdf.h"

#include <gtest/gtest.h>

#include <numbers>

#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

using test_support::direction_from_degrees;

constexpr std::size_t kSamples = 100000;
const double kViewAngles[] = {0, 30, 60, 85, 120};  // 120: wo below the surface, shaded on its own side
const double kSignificance = test_support::sidak_significance(0.01, std::size(kViewAngles));

TEST(LambertBsdf, SamplesMatchPdf) {
    const LambertBsdf bsdf(Rgb(0.5f));
    for (double theta : kViewAngles) {
        const auto fit = test_support::sampling_fit(bsdf, direction_from_degrees(theta, 40), kSamples);
        EXPECT_GT(fit.chi_square.p_value, kSignificance) << theta;
        EXPECT_NEAR(fit.pdf_integral, 1.0, 1e-3) << theta;  // nothing lost: the whole lobe is above the horizon
    }
}

TEST(LambertBsdf, WrongPdfIsRejected) {
    // Proves the test can fail: cosine-weighted samples judged against a uniform hemisphere.
    const LambertBsdf bsdf(Rgb(0.5f));
    const auto uniform = [](const Vec3f& wi) { return wi.z > 0 ? 0.5 / std::numbers::pi : 0.0; };
    EXPECT_LT(test_support::sampling_fit(bsdf, direction_from_degrees(30), kSamples, uniform).chi_square.p_value, 1e-12);
}

TEST(LambertBsdf, EvalIsReflectanceOverPiOnWosSideOnly) {
    const LambertBsdf bsdf(Rgb(0.2f, 0.5f, 1.0f));
    const Vec3f up = direction_from_degrees(30, 10), down = direction_from_degrees(150, 80);
    EXPECT_FLOAT_EQ(bsdf.eval(up, direction_from_degrees(70, 200)).b, std::numbers::inv_pi_v<float>);
    EXPECT_FLOAT_EQ(bsdf.eval(down, direction_from_degrees(100, 20)).r, 0.2f * std::numbers::inv_pi_v<float>);
    EXPECT_TRUE(bsdf.eval(up, down).is_black());
    EXPECT_EQ(bsdf.pdf(up, down), 0.0f);
    EXPECT_EQ(bsdf.pdf(down, up), 0.0f);
}

TEST(LambertBsdf, IsReciprocal) {
    const LambertBsdf bsdf(Rgb(0.7f));
    for (std::size_t i = 0; i < 100; ++i) {
        const auto r = test_support::bsdf_random(i);
        const Vec3f a = direction_from_degrees(89 * r.u[0], 360 * r.u[1]);
        const Vec3f b = direction_from_degrees(89 * r.u_lobe, 360 * r.u[0]);
        EXPECT_EQ(bsdf.eval(a, b), bsdf.eval(b, a));
    }
}

TEST(LambertBsdf, WhiteFurnaceIsExactlyOne) {
    const LambertBsdf bsdf(Rgb(1.0f));
    for (double theta : {0.0, 45.0, 89.9, 135.0}) {
        const auto albedo = test_support::estimate_albedo(bsdf, direction_from_degrees(theta), 10000);
        EXPECT_NEAR(albedo.mean.g, 1.0f, 1e-5f) << theta;
    }
}

TEST(LambertBsdf, SampleAgreesWithEvalAndPdf) {
    const LambertBsdf bsdf(Rgb(0.3f, 0.6f, 0.9f));
    const Vec3f wo = direction_from_degrees(50, 10);
    for (std::size_t i = 0; i < 1000; ++i) {
        const auto r = test_support::bsdf_random(i);
        const std::optional<BsdfSample> s = bsdf.sample(wo, r.u_lobe, r.u);
        ASSERT_TRUE(s);
        EXPECT_FLOAT_EQ(s->pdf, bsdf.pdf(wo, s->wi));
        EXPECT_NEAR(s->weight.g, 0.6f, 1e-5f);
        EXPECT_FALSE(s->is_delta || s->is_transmission);
    }
}

// The weight f·cos/pdf is the reflectance exactly, not its value after a multiplication and a division, on both sides.
TEST(LambertBsdf, SampleWeightIsTheReflectanceItself) {
    const Rgb reflectance(0.3f, 0.6f, 0.9f);
    const LambertBsdf bsdf(reflectance);
    for (const double theta : {10.0, 50.0, 89.0, 130.0}) {
        const Vec3f wo = direction_from_degrees(theta, 10);
        for (std::size_t i = 0; i < 1000; ++i) {
            const auto r = test_support::bsdf_random(i);
            const std::optional<BsdfSample> s = bsdf.sample(wo, r.u_lobe, r.u);
            if (!s) continue;
            EXPECT_EQ(s->weight, reflectance) << theta << " " << i;
            EXPECT_GT(s->pdf, 0.0f);
            EXPECT_GT(s->wi.z * wo.z, 0.0f);
        }
    }
}

TEST(LambertBsdf, DegenerateDirectionsGiveNothingOrFiniteValues) {
    const LambertBsdf bsdf(Rgb(0.5f));
    EXPECT_FALSE(bsdf.sample(Vec3f(1, 0, 0), 0.5f, {0.5f, 0.5f}));
    for (const Vec3f& wo : {Vec3f(0, 0, 1), direction_from_degrees(89.9), direction_from_degrees(90.1)}) {
        for (std::size_t i = 0; i < 1000; ++i) {
            const auto r = test_support::bsdf_random(i);
            const std::optional<BsdfSample> s = bsdf.sample(wo, r.u_lobe, r.u);
            if (s) {
                ASSERT_TRUE(s->weight.is_finite() && is_finite(s->wi));
            }
        }
    }
}

}  // namespace
}  // namespace isotrace
