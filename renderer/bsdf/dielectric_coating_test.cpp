#include "renderer/bsdf/dielectric_coating.h"

#include <gtest/gtest.h>

#include "renderer/bsdf/fresnel.h"
#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

using test_support::direction_from_degrees;

TEST(DielectricCoating, SmoothCoatingReflectsTheFresnelShare) {
    const DielectricCoating coating(1.5f, 0);
    for (float mu : {1.0f, 0.5f, 0.1f}) EXPECT_EQ(coating.reflectance(mu), fresnel_dielectric(mu, 1.5f));
    EXPECT_NEAR(coating.mean_transmittance(), 1 - diffuse_fresnel_reflectance(1.5f), 1e-5f);
    // Known value for glass (e.g. Weidlich and Wilkie 2007): about 60% of diffuse light from inside returns.
    EXPECT_NEAR(coating.internal_diffuse_reflectance(), 0.596f, 0.005f);
}

TEST(DielectricCoating, RoughReflectanceTableMatchesMonteCarlo) {
    for (float alpha : {0.05f, 0.3f, 0.8f}) {
        const DielectricCoating coating(1.5f, alpha);
        for (double theta : {0.0, 45.0, 75.0, 88.0}) {
            const Vec3f wo = direction_from_degrees(theta);
            double sum = 0;
            constexpr std::size_t samples = 50000;
            for (std::size_t i = 0; i < samples; ++i) {
                const Vec3f wi = coating.sample_reflection(wo, test_support::bsdf_random(i).u);
                if (wi.z > 0) sum += coating.reflection(wo, wi) * wi.z / coating.reflection_pdf(wo, wi);
            }
            // Near grazing both the 64-entry table and the estimate (noisier weights) are off by up to ~1%.
            const double estimate = sum / samples;
            EXPECT_NEAR(coating.reflectance(wo.z), estimate, 0.02 * estimate + 1e-3) << alpha << " " << theta;
        }
    }
}

}  // namespace
}  // namespace isotrace
