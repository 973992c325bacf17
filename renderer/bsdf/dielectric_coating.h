#pragma once
// A clear dielectric layer of IOR eta over some base, seen from outside (z up): smooth when alpha = 0, else an
// isotropic GGX surface. Describes the layer's specular reflection lobe and how much light it lets through
// towards the base. The tables cost a few milliseconds, so materials build a coating once and BSDFs at
// shading points refer to it.
#include <array>
#include <vector>

#include "renderer/bsdf/ggx.h"

namespace isotrace {

class DielectricCoating {
public:
    // eta > 1, alpha >= 0.
    DielectricCoating(float eta, float alpha);

    float eta() const { return eta_; }
    bool is_smooth() const { return smooth_; }

    // Directional albedo E(mu) of the reflection lobe for cos theta = mu in [0, 1]: the Fresnel reflectance
    // when smooth, else integral of f_coat cos over the hemisphere (tabulated; the microfacet lobe only).
    float reflectance(float mu) const;
    // T(mu) = 1 - E(mu): the share of light arriving from mu that is not reflected by the coating, i.e. what
    // enters towards the base. Using 1 - E rather than 1 - F keeps a rough coating energy-conserving.
    float transmittance(float mu) const { return 1.0f - reflectance(mu); }
    // Cosine-weighted hemispherical average 2 * integral of T(mu) mu dmu: the share of diffuse light from outside
    // that enters.
    float mean_transmittance() const { return mean_transmittance_; }
    // Share of diffuse light from inside that the (smooth) interface reflects back down, with total internal
    // reflection: F_int = 1 - (1 - F_dr) / eta^2, which follows from reciprocity of the interface (radiance
    // scales by eta^2 across it) and F_dr = diffuse_fresnel_reflectance(eta) from outside.
    float internal_diffuse_reflectance() const { return internal_diffuse_reflectance_; }

    // The rough reflection lobe (zero when smooth, where the mirror direction is a delta): wo.z > 0, wi.z > 0.
    float reflection(const Vec3f& wo, const Vec3f& wi) const;
    float reflection_pdf(const Vec3f& wo, const Vec3f& wi) const;
    Vec3f sample_reflection(const Vec3f& wo, std::array<float, 2> u) const;

private:
    float tabulated_reflectance(float mu) const;

    float eta_;
    bool smooth_;
    GgxDistribution ggx_;
    std::vector<float> reflectance_table_;  // rough only: E at mu = (i / (n - 1))^2, dense near grazing
    float mean_transmittance_ = 0;
    float internal_diffuse_reflectance_ = 0;
};

}  // namespace isotrace
