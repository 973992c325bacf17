#pragma once
// Metal: a perfect mirror when alpha_x = alpha_y = 0, otherwise GGX microfacet reflection, with the exact
// conductor Fresnel term. Two-sided (see TwoSidedBsdf). Single scattering only: energy that would bounce
// between microfacets is lost, so rough metals come out slightly darker than measured ones.
#include "renderer/bsdf/fresnel.h"
#include "renderer/bsdf/ggx.h"
#include "renderer/bsdf/two_sided_bsdf.h"

namespace isotrace {

class ConductorBsdf final : public TwoSidedBsdf<ConductorBsdf> {
public:
    // Alphas >= 0, both zero or both positive.
    ConductorBsdf(const ComplexIor& ior, float alpha_x, float alpha_y);

    bool has_delta_lobe() const { return smooth_; }
    bool is_fully_delta() const { return smooth_; }
    bool chooses_lobe() const { return false; }

private:
    friend class TwoSidedBsdf<ConductorBsdf>;
    Rgb eval_upper(const Vec3f& wo, const Vec3f& wi) const;
    float pdf_upper(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sample_upper(const Vec3f& wo, float u_lobe, std::array<float, 2> u) const;

    ComplexIor ior_;
    GgxDistribution ggx_;
    bool smooth_;
};

}  // namespace isotrace
