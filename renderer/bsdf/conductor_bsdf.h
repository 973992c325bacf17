#pragma once
// Metal: a perfect mirror when alpha_x = alpha_y = 0, otherwise GGX microfacet reflection, with the exact
// conductor Fresnel term. Two-sided (see TwoSidedBsdf). Single scattering only: energy that would bounce
// between microfacets is lost, so rough metals come out slightly darker than measured ones.
#include "renderer/bsdf/fresnel.h"
#include "renderer/bsdf/ggx.h"
#include "renderer/bsdf/two_sided_bsdf.h"

namespace isotrace {

class ConductorBsdf final : public TwoSidedBsdf {
public:
    // Alphas >= 0, both zero or both positive.
    ConductorBsdf(const ComplexIor& ior, float alpha_x, float alpha_y);

    bool has_delta_lobe() const override { return smooth_; }
    bool is_fully_delta() const override { return smooth_; }

private:
    Rgb eval_upper(const Vec3f& wo, const Vec3f& wi) const override;
    float pdf_upper(const Vec3f& wo, const Vec3f& wi) const override;
    std::optional<BsdfSample> sample_upper(const Vec3f& wo, float u_lobe, std::array<float, 2> u) const override;

    ComplexIor ior_;
    GgxDistribution ggx_;
    bool smooth_;
};

}  // namespace isotrace
