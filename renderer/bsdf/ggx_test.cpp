#include "renderer/bsdf/ggx.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "renderer/bsdf/conductor_bsdf.h"
#include "renderer/bsdf/dielectric_bsdf.h"
#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

using test_support::BsdfRandom;
using test_support::direction_from_degrees;
using test_support::sphere_integral;

using test_support::kRoughnesses;
using test_support::Roughness;
using test_support::view_at;
const double kViewAngles[] = {0, 30, 60, 85};  // degrees from the normal, at azimuth 30 degrees
constexpr std::size_t kSamples = 100000;
const double kSignificance = test_support::sidak_significance(0.01, 4 * 4);

TEST(Ggx, RoughnessMapsToItsSquare) {
    EXPECT_FLOAT_EQ(roughness_to_alpha(0.5f), 0.25f);
    EXPECT_FLOAT_EQ(roughness_to_alpha(1.0f), 1.0f);
}

TEST(Ggx, ProjectedMicrofacetAreaIsOne) {
    for (const Roughness& r : {Roughness{0.3f, 0.3f}, Roughness{0.8f, 0.8f}, Roughness{0.1f, 0.6f}}) {
        const GgxDistribution ggx(r.alpha_x, r.alpha_y);
        EXPECT_NEAR(sphere_integral([&](const Vec3f& m) { return ggx.d(m) * m.z; }), 1.0, 1e-3) << r.alpha_x;
    }
}

TEST(Ggx, MaskingIsTheSameFromBothSides) {
    const GgxDistribution ggx(0.2f, 0.5f);
    const Vec3f w = view_at(60);
    EXPECT_FLOAT_EQ(ggx.g1(w), ggx.g1(-w));
    EXPECT_FLOAT_EQ(ggx.g1(Vec3f(0, 0, 1)), 1.0f);
    EXPECT_EQ(ggx.g1(Vec3f(1, 0, 0)), 0.0f);
    EXPECT_LE(ggx.g2(w, view_at(30)), std::min(ggx.g1(w), ggx.g1(view_at(30))));
}

class GgxVisibleNormalSampling : public testing::TestWithParam<std::tuple<Roughness, double>> {};

TEST_P(GgxVisibleNormalSampling, MatchesPdf) {
    const auto [r, theta] = GetParam();
    const GgxDistribution ggx(r.alpha_x, r.alpha_y);
    const Vec3f w = view_at(theta);
    const auto fit = test_support::direction_sampling_fit(
        [&](const BsdfRandom& random) { return std::optional(ggx.sample_visible_normal(w, random.u)); }, kSamples,
        [&](const Vec3f& m) { return ggx.visible_normal_pdf(w, m); });
    EXPECT_GT(fit.chi_square.p_value, kSignificance);
    // The visible normals' density integrates to one only if G1 is the masking that matches D: the visible
    // projected area equals the projected macrosurface area (Heitz 2014, eq. 7).
    EXPECT_NEAR(fit.pdf_integral, 1.0, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(RoughnessAndView, GgxVisibleNormalSampling,
                         testing::Combine(testing::ValuesIn(kRoughnesses), testing::ValuesIn(kViewAngles)),
                         test_support::roughness_and_view_name);

TEST(Ggx, WrongVisibleNormalPdfIsRejected) {
    // Proves the sampling test can fail: the plain distribution of normals D(m) m.z, i.e. the pdf without the
    // visible-normal term, against samples of the visible normals from 60 degrees.
    const GgxDistribution ggx(0.3f, 0.3f);
    const Vec3f w = view_at(60);
    const auto fit = test_support::direction_sampling_fit(
        [&](const BsdfRandom& random) { return std::optional(ggx.sample_visible_normal(w, random.u)); }, kSamples,
        [&](const Vec3f& m) { return ggx.d(m) * m.z; });
    EXPECT_LT(fit.chi_square.p_value, 1e-12);
}

TEST(Ggx, SamplesBelowTheSurfaceSeeTheMirroredMicrosurface) {
    const GgxDistribution ggx(0.3f, 0.3f);
    const Vec3f w = view_at(45);
    for (std::size_t i = 0; i < 1000; ++i) {
        const BsdfRandom random = test_support::bsdf_random(i);
        const Vec3f m = ggx.sample_visible_normal(-w, random.u);
        EXPECT_EQ(m, ggx.sample_visible_normal(w, random.u));
        EXPECT_FLOAT_EQ(ggx.visible_normal_pdf(-w, m), ggx.visible_normal_pdf(w, m));
    }
}

TEST(Ggx, SamplingStaysFiniteInExtremeCases) {
    const Vec3f views[] = {Vec3f(0, 0, 1), direction_from_degrees(89.9), Vec3f(1, 0, 0), direction_from_degrees(0.001)};
    for (float alpha : {1e-6f, 1e-3f, 1.0f}) {
        const GgxDistribution ggx(alpha, alpha);
        for (const Vec3f& w : views) {
            for (std::size_t i = 0; i < 1000; ++i) {
                const Vec3f m = ggx.sample_visible_normal(w, test_support::bsdf_random(i).u);
                ASSERT_TRUE(is_finite(m) && m.z > 0) << alpha;
                ASSERT_NEAR(length(m), 1.0f, 1e-5f);
                ASSERT_TRUE(std::isfinite(ggx.visible_normal_pdf(w, m))) << alpha;
            }
        }
    }
}

// Roughness 1e-5 (alpha 1e-10) under an environment made a third of the samples NaN: the densities, ~1/alpha^2, are
// squared by the path tracer's power heuristic. Every alpha down to the smallest float now samples as kMinGgxAlpha
// does: finite, consistent samples whose squared pdf keeps a wide margin, and a perfect mirror's full energy.
TEST(Ggx, TinyAlphasSampleFinitelyAndKeepTheirEnergy) {
    const ComplexIor perfect_mirror{Rgb(1.0f), Rgb(1e4f)};
    for (float alpha : {kMinGgxAlpha, 1e-7f, 1e-8f, 1e-10f, 1e-12f, 1e-30f, std::numeric_limits<float>::denorm_min()}) {
        const GgxDistribution ggx(alpha, alpha);
        EXPECT_EQ(ggx.alpha_x(), kMinGgxAlpha);
        EXPECT_EQ(ggx.alpha_y(), kMinGgxAlpha);
        const ConductorBsdf conductor(perfect_mirror, alpha, alpha);
        const DielectricBsdf dielectric(1.5f, alpha, alpha);
        for (double theta : {0.0, 30.0, 85.0, 89.9, 89.999}) {
            const Vec3f wo = view_at(theta);
            for (const SurfaceBsdf& bsdf : {SurfaceBsdf(conductor), SurfaceBsdf(dielectric)}) {
                EXPECT_EQ(test_support::count_bad_samples(bsdf, wo, 2000), 0u) << alpha << " " << theta;
                for (std::size_t i = 0; i < 2000; ++i) {
                    const BsdfRandom r = test_support::bsdf_random(i);
                    const auto sample = bsdf.sample(wo, r.u_lobe, r.u, TransportMode::Radiance);
                    if (sample) { ASSERT_LT(sample->pdf * sample->pdf, 1e32f) << alpha << " " << theta; }
                }
            }
            const auto albedo = test_support::estimate_albedo(SurfaceBsdf(conductor), wo, 2000);
            EXPECT_LE(albedo.mean.r, 1.0f + 1e-4f) << alpha << " " << theta;
            if (theta < 89) { EXPECT_GT(albedo.mean.r, 0.99f) << alpha << " " << theta; }  // a mirror's, nearly all
        }
    }
}

}  // namespace
}  // namespace isotrace
