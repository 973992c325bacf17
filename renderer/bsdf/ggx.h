#pragma once
// Trowbridge-Reitz (GGX) microfacet distribution with anisotropic roughness (alpha_x along the tangent x,
// alpha_y along y), the height-correlated Smith masking-shadowing, and sampling of the normals visible from a
// direction (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)).
#include <array>

#include "renderer/math/vec3.h"

namespace isotrace {

// Perceptually linear roughness in [0, 1] to GGX alpha: alpha = roughness^2 (Burley 2012, "Physically-Based
// Shading at Disney"), so equal steps of roughness look like equal steps of blur.
float roughness_to_alpha(float roughness);

// The smallest alpha a distribution uses (roughness 0.001); smaller ones are raised to it. The densities grow as
// 1/alpha^2 (to ~5e15 here, seen from grazing angles), and the path tracer's power heuristic squares them: below
// ~1e-8 the squares overflow float and samples become NaN. Sampling, eval and pdf stay finite and consistent, and
// the lobe keeps its energy, down to this value with a margin of 1e6 in those squares (ggx_test.cpp).
inline constexpr float kMinGgxAlpha = 1e-6f;

class GgxDistribution {
public:
    // Both alphas > 0 (a smooth surface is a delta lobe and handled by the models themselves); each is raised to
    // kMinGgxAlpha at least.
    GgxDistribution(float alpha_x, float alpha_y);

    float alpha_x() const { return alpha_x_; }
    float alpha_y() const { return alpha_y_; }

    // Density of microfacet normals m per solid angle, normalised so that the projected areas sum to one:
    // integral of D(m) m.z dm = 1. Zero for m.z <= 0.
    float d(const Vec3f& m) const;
    // Smith's Lambda(w); depends on |w.z| only, so the microsurface looks the same from either side.
    float lambda(const Vec3f& w) const;
    // Masking of the microsurface seen from w.
    float g1(const Vec3f& w) const;
    // Height-correlated masking-shadowing 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014, "Understanding the
    // Masking-Shadowing Function"): tall microfacets unmasked from wo tend to be unshadowed from wi too.
    float g2(const Vec3f& wo, const Vec3f& wi) const;

    // A normal visible from w, with density visible_normal_pdf(w, m). Directions below the surface see the
    // same microsurface from underneath: they sample as their mirror image -w, and m.z > 0 always.
    Vec3f sample_visible_normal(const Vec3f& w, std::array<float, 2> u) const;
    // D_w(m) = G1(w) max(0, w'.m) D(m) / |w.z| with w' = w on w's side (Heitz 2018, eq. 1), per solid angle.
    float visible_normal_pdf(const Vec3f& w, const Vec3f& m) const;

private:
    float alpha_x_, alpha_y_;
};

}  // namespace isotrace
