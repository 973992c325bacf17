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
    // The weight f·cos/pdf = (R/π)·cos/(cos/π) is the reflectance itself: taken as it is, it is exact and costs
    // neither the evaluation nor the division (the pdf is still the cosine's, for multiple importance sampling).
    // A direction lost to rounding at the horizon (z = 0, pdf 0) is discarded by TwoSidedBsdf::sample; any z > 0
    // a sample can have gives a positive pdf.
    std::optional<BsdfSample> sample_upper(const Vec3f&, float, std::array<float, 2> u) const {
        BsdfSample sample;
        sample.wi = square_to_cosine_hemisphere(u);
        sample.pdf = square_to_cosine_hemisphere_pdf(sample.wi);
        sample.weight = reflectance_;
        return sample;
    }

    Rgb reflectance_;
};

}  // namespace isotrace
