#include "renderer/bsdf/lambert_bsdf.h"

#include <numbers>

#include "renderer/sampling/warps.h"

namespace isotrace {

Rgb LambertBsdf::eval_upper(const Vec3f&, const Vec3f&) const {
    return reflectance_ * std::numbers::inv_pi_v<float>;
}

float LambertBsdf::pdf_upper(const Vec3f&, const Vec3f& wi) const {
    return square_to_cosine_hemisphere_pdf(wi);
}

std::optional<BsdfSample> LambertBsdf::sample_upper(const Vec3f& wo, float, std::array<float, 2> u) const {
    return sample_towards(*this, wo, square_to_cosine_hemisphere(u), TransportMode::Radiance);
}

}  // namespace isotrace
