#pragma once
// Lambertian reflection f = R / pi, sampled proportionally to the cosine. Two-sided (see TwoSidedBsdf).
#include "renderer/bsdf/two_sided_bsdf.h"

namespace isotrace {

class LambertBsdf final : public TwoSidedBsdf {
public:
    // reflectance in [0, 1] per channel.
    explicit LambertBsdf(const Rgb& reflectance) : reflectance_(reflectance) {}

    bool has_delta_lobe() const override { return false; }
    bool is_fully_delta() const override { return false; }

private:
    Rgb eval_upper(const Vec3f& wo, const Vec3f& wi) const override;
    float pdf_upper(const Vec3f& wo, const Vec3f& wi) const override;
    std::optional<BsdfSample> sample_upper(const Vec3f& wo, float u_lobe, std::array<float, 2> u) const override;

    Rgb reflectance_;
};

}  // namespace isotrace
