#pragma once
// Lambertian reflection f = R / pi, sampled proportionally to the cosine. Two-sided (see TwoSidedBsdf).
#include <numbers>

#include "renderer/bsdf/two_sided_bsdf.h"
#include "renderer/sampling/warps.h"

namespace isotrace {

class LambertBsdf final : public TwoSidedBsdf<LambertBsdf> {
public:
    // reflectance in [0, 1] per channel.
    explicit LambertBsdf(const Rgb& reflectance) : reflectance_(reflectance) {}

    bool has_delta_lobe() const { return false; }
    bool is_fully_delta() const { return false; }
    bool chooses_lobe() const { return false; }

private:
    friend class TwoSidedBsdf<LambertBsdf>;
    Rgb eval_upper(const Vec3f&, const Vec3f&) const { return reflectance_ * std::numbers::inv_pi_v<float>; }
    float pdf_upper(const Vec3f&, const Vec3f& wi) const { return square_to_cosine_hemisphere_pdf(wi); }
    std::optional<BsdfSample> sample_upper(const Vec3f& wo, float, std::array<float, 2> u) const {
        return sample_towards(*this, wo, square_to_cosine_hemisphere(u), TransportMode::Radiance);
    }

    Rgb reflectance_;
};

}  // namespace isotrace
