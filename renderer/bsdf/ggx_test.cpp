#include "renderer/bsdf/ggx.h"

#include <gtest/gtest.h>

#include <string>

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

}  // namespace
}  // namespace isotrace
