#include "renderer/bsdf/conductor_bsdf.h"

#include "renderer/bsdf/microfacet.h"
#include "renderer/bsdf/shading_frame.h"

namespace isotrace {

ConductorBsdf::ConductorBsdf(const ComplexIor& ior, float alpha_x, float alpha_y)
    : ior_(ior), ggx_(alpha_x, alpha_y), smooth_(alpha_x == 0 && alpha_y == 0) {}

Rgb ConductorBsdf::eval_upper(const Vec3f& wo, const Vec3f& wi) const {
    if (smooth_) return {};
    const std::optional<Vec3f> m = microfacet_normal(wo, wi, 1.0f);
    if (!m) return {};
    return fresnel_conductor(dot(wo, *m), ior_) * microfacet_reflection(ggx_, wo, wi, *m);
}

float ConductorBsdf::pdf_upper(const Vec3f& wo, const Vec3f& wi) const {
    if (smooth_) return 0;
    const std::optional<Vec3f> m = microfacet_normal(wo, wi, 1.0f);
    return m ? microfacet_reflection_pdf(ggx_, wo, *m) : 0.0f;
}

std::optional<BsdfSample> ConductorBsdf::sample_upper(const Vec3f& wo, float, std::array<float, 2> u) const {
    if (smooth_) {
        BsdfSample mirror;
        mirror.weight = fresnel_conductor(wo.z, ior_);
        mirror.wi = mirror_z(-wo);
        mirror.pdf = 1;
        mirror.is_delta = true;
        return mirror;
    }
    const Vec3f wi = reflect(wo, ggx_.sample_visible_normal(wo, u));
    return sample_towards(*this, wo, wi, TransportMode::Radiance);
}

}  // namespace isotrace
