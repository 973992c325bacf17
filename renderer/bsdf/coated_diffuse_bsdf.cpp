#include "renderer/bsdf/coated_diffuse_bsdf.h"

#include <numbers>

#include "renderer/bsdf/shading_frame.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

Rgb effective_reflectance(const Rgb& r, float internal_reflectance) {
    const auto channel = [internal_reflectance](float c) {
        return c * (1.0f - internal_reflectance) / (1.0f - c * internal_reflectance);
    };
    return {channel(r.r), channel(r.g), channel(r.b)};
}

}  // namespace

CoatedDiffuseBsdf::CoatedDiffuseBsdf(const DielectricCoating& coating, const Rgb& reflectance)
    : coating_(&coating),
      effective_reflectance_(effective_reflectance(reflectance, coating.internal_diffuse_reflectance())) {}

float CoatedDiffuseBsdf::coating_probability(const Vec3f& wo) const {
    const float coat = coating_->reflectance(wo.z);
    const Rgb& r = effective_reflectance_;
    const float base = coating_->transmittance(wo.z) * (r.r + r.g + r.b) / 3.0f;
    return coat + base > 0 ? coat / (coat + base) : 1.0f;
}

Rgb CoatedDiffuseBsdf::eval_upper(const Vec3f& wo, const Vec3f& wi) const {
    const float base = coating_->transmittance(wo.z) * coating_->transmittance(wi.z) /
                       (std::numbers::pi_v<float> * coating_->mean_transmittance());
    return effective_reflectance_ * base + Rgb(coating_->reflection(wo, wi));
}

float CoatedDiffuseBsdf::pdf_upper(const Vec3f& wo, const Vec3f& wi) const {
    const float p_coat = coating_probability(wo);
    return p_coat * coating_->reflection_pdf(wo, wi) + (1.0f - p_coat) * square_to_cosine_hemisphere_pdf(wi);
}

std::optional<BsdfSample> CoatedDiffuseBsdf::sample_upper(const Vec3f& wo, float u_lobe, std::array<float, 2> u) const {
    const float p_coat = coating_probability(wo);
    if (u_lobe >= p_coat) return sample_towards(*this, wo, square_to_cosine_hemisphere(u), TransportMode::Radiance);
    if (!coating_->is_smooth()) return sample_towards(*this, wo, coating_->sample_reflection(wo, u), TransportMode::Radiance);
    BsdfSample mirror;
    mirror.weight = Rgb(coating_->reflectance(wo.z) / p_coat);
    mirror.wi = mirror_z(-wo);
    mirror.pdf = p_coat;
    mirror.is_delta = true;
    return mirror;
}

}  // namespace isotrace
