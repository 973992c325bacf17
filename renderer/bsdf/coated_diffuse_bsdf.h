#pragma once
// "Plastic": a clear dielectric coating (smooth or rough GGX, see DielectricCoating) over a Lambertian base of
// reflectance R. Two-sided (see TwoSidedBsdf).
//
//   f(wo, wi) = f_coat(wo, wi) + R_eff T(wo) T(wi) / (pi T_mean)
//   R_eff     = R (1 - F_int) / (1 - R F_int)
//
// f_coat is the coating's reflection lobe (a delta mirror of weight F(wo) when smooth), T = 1 - E the light
// the coating lets through at each end, T_mean its cosine-weighted average and F_int the internal diffuse
// reflectance of the interface. R_eff sums the light that bounces between base and coating before leaving
// (R (1 - F_int) sum (R F_int)^n). For a smooth coating T_mean = 1 - F_dr = eta^2 (1 - F_int), and the model is
// exactly Weidlich and Wilkie 2007 ("Arbitrarily Layered Micro-Facet Surfaces") with a Lambertian base and no
// absorption, i.e. the diffuse part of Mitsuba's "plastic":
// (1 - F(wo)) (1 - F(wi)) R / (pi eta^2 (1 - R F_int)). Dividing by T_mean instead of eta^2 (1 - F_int) keeps
// the rough variant exact too:
//  - reciprocal, since T(wo) T(wi) is symmetric and so is f_coat;
//  - energy-conserving, since the base's albedo is T(wo) R_eff <= 1 - E(wo), so the total is at most 1
//    (and exactly 1 when R = 1 and the coating is smooth).
#include "renderer/bsdf/dielectric_coating.h"
#include "renderer/bsdf/two_sided_bsdf.h"

namespace isotrace {

class CoatedDiffuseBsdf final : public TwoSidedBsdf<CoatedDiffuseBsdf> {
public:
    // The coating must outlive the BSDF. reflectance in [0, 1] per channel.
    CoatedDiffuseBsdf(const DielectricCoating& coating, const Rgb& reflectance);

    bool has_delta_lobe() const { return coating_->is_smooth(); }
    bool is_fully_delta() const { return false; }
    bool chooses_lobe() const { return true; }  // coating or base

private:
    friend class TwoSidedBsdf<CoatedDiffuseBsdf>;
    Rgb eval_upper(const Vec3f& wo, const Vec3f& wi) const;
    float pdf_upper(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sample_upper(const Vec3f& wo, float u_lobe, std::array<float, 2> u) const;

    // Probability of sampling the coating rather than the base: their albedos' share at wo.
    float coating_probability(const Vec3f& wo) const;

    const DielectricCoating* coating_;
    Rgb effective_reflectance_;  // R_eff
};

}  // namespace isotrace
