// SurfaceBsdf: the one switch in front of the models. Its empty state scatters nothing, and a model's
// chooses_lobe() is what the path tracer trusts to leave u_lobe's dimensions uncomputed: when it says false,
// sample() must not depend on u_lobe; when it says true, it must (or the flag costs work for nothing).
#include "renderer/bsdf/surface_bsdf.h"

#include <gtest/gtest.h>

#include <vector>

#include "renderer/bsdf/shading_frame.h"
#include "tests/support/bsdf_checks.h"

namespace isotrace {
namespace {

// Whether sample() gives anything different for a low and a high u_lobe, over a spread of wo and u.
bool sample_depends_on_u_lobe(const SurfaceBsdf& bsdf) {
    for (const double theta : {0.0, 30.0, 60.0, 85.0, 120.0, 170.0})
        for (std::size_t i = 0; i < 64; ++i) {
            const Vec3f wo = test_support::view_at(theta);
            const test_support::BsdfRandom r = test_support::bsdf_random(i);
            const auto low = bsdf.sample(wo, 0.02f, r.u), high = bsdf.sample(wo, 0.98f, r.u);
            if (low.has_value() != high.has_value()) return true;
            if (low && (low->wi != high->wi || !(low->weight == high->weight) || low->pdf != high->pdf)) return true;
        }
    return false;
}

TEST(SurfaceBsdf, EmptyScattersNothing) {
    const SurfaceBsdf none;
    EXPECT_FALSE(none.scatters());
    EXPECT_TRUE(none.eval({0, 0, 1}, {0, 0, 1}).is_black());
    EXPECT_EQ(none.pdf({0, 0, 1}, {0, 0, 1}), 0.0f);
    EXPECT_FALSE(none.sample({0, 0, 1}, 0.5f, {0.5f, 0.5f}));
    EXPECT_FALSE(none.chooses_lobe());
}

SurfaceBsdf principled(const PrincipledParameters& parameters) { return PrincipledBsdf(parameters); }

TEST(SurfaceBsdf, ChoosesLobeExactlyWhenSamplingReadsTheLobeNumber) {
    const DielectricCoating smooth_coating(1.5f, 0), rough_coating(1.5f, 0.3f);
    const std::vector<SurfaceBsdf> models = {
        LambertBsdf(Rgb(0.5f)),
        ConductorBsdf({Rgb(0.2f), Rgb(3.0f)}, 0, 0),
        ConductorBsdf({Rgb(0.2f), Rgb(3.0f)}, 0.3f, 0.3f),
        DielectricBsdf(1.5f, 0, 0),
        DielectricBsdf(1.5f, 0.3f, 0.3f),
        CoatedDiffuseBsdf(smooth_coating, Rgb(0.5f)),
        CoatedDiffuseBsdf(rough_coating, Rgb(0.5f)),
        principled({.specular = 0}),                                    // exactly Lambert
        principled({.metallic = 1, .roughness = 0}),                    // one delta mirror
        principled({.metallic = 1, .roughness = 0.4f}),                 // GGX and multiple scattering
        principled({.roughness = 0.4f}),                                // specular over diffuse
        principled({.roughness = 0, .transmission = 1}),                // glass
        principled({.roughness = 0.3f, .clearcoat = 1, .sheen = 1}),
    };
    for (std::size_t m = 0; m < models.size(); ++m) {
        EXPECT_TRUE(models[m].scatters()) << m;
        EXPECT_EQ(models[m].chooses_lobe(), sample_depends_on_u_lobe(models[m])) << "model " << m;
    }
}

// The path tracer takes a sampled direction into the world frame without normalising it again: every model must
// sample unit directions (to within a few roundings), and an orthonormal shading frame keeps them so.
TEST(SurfaceBsdf, SampledDirectionsAreUnitInTheWorldToo) {
    const DielectricCoating rough_coating(1.5f, 0.3f);
    const std::vector<SurfaceBsdf> models = {
        LambertBsdf(Rgb(0.5f)),
        ConductorBsdf({Rgb(0.2f), Rgb(3.0f)}, 0.3f, 0.1f),
        DielectricBsdf(1.5f, 0, 0),
        DielectricBsdf(1.5f, 0.3f, 0.3f),
        CoatedDiffuseBsdf(rough_coating, Rgb(0.5f)),
        principled({.roughness = 0.4f}),
        principled({.roughness = 0.3f, .transmission = 1}),
        principled({.roughness = 0.3f, .clearcoat = 1, .sheen = 1}),
    };
    constexpr float kTolerance = 4e-6f;  // of the squared length: some ten roundings of 6e-8 each
    for (std::size_t m = 0; m < models.size(); ++m)
        for (std::size_t i = 0; i < 512; ++i) {
            const test_support::BsdfRandom r = test_support::bsdf_random(i);
            // A frame from a normal and a tangent that is not perpendicular to it (as meshes give them).
            const Vec3f normal = normalize(Vec3f(0.3f, -0.5f, 0.8f) + Vec3f(r.u[1], 0.1f * r.u_lobe, -r.u[0]));
            const ShadingFrame frame(normal, Vec3f(1.0f, 0.2f * r.u[0], 0.3f));
            const Vec3f wo = test_support::view_at(170.0 * r.u_lobe);
            const std::optional<BsdfSample> s = models[m].sample(wo, r.u_lobe, r.u);
            if (!s) continue;
            EXPECT_NEAR(dot(s->wi, s->wi), 1.0f, kTolerance) << "model " << m << " sample " << i;
            const Vec3f world = frame.to_world(s->wi);
            EXPECT_NEAR(dot(world, world), 1.0f, kTolerance) << "model " << m << " sample " << i;
        }
}

}  // namespace
}  // namespace isotrace
