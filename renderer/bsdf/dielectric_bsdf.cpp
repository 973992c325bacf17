#include "renderer/bsdf/dielectric_bsdf.h"

#include <cmath>

#include "renderer/bsdf/fresnel.h"
#include "renderer/bsdf/microfacet.h"
#include "renderer/bsdf/shading_frame.h"

namespace isotrace {

DielectricBsdf::DielectricBsdf(float eta, float alpha_x, float alpha_y, const Rgb& transmission_tint)
    : eta_(eta), ggx_(alpha_x, alpha_y), tint_(transmission_tint), smooth_(alpha_x == 0 && alpha_y == 0) {}

Rgb DielectricBsdf::transmission_scale(float eta_rel, TransportMode mode) const {
    return mode == TransportMode::Radiance ? tint_ * (1.0f / (eta_rel * eta_rel)) : tint_;
}

std::optional<DielectricBsdf::Connection> DielectricBsdf::connect(const Vec3f& wo, const Vec3f& wi) const {
    const float eta_rel = same_hemisphere(wo, wi) ? 1.0f : refraction_eta(wo);
    const std::optional<Vec3f> m = microfacet_normal(wo, wi, eta_rel);
    if (!m) return std::nullopt;
    return Connection{*m, eta_rel};
}

Rgb DielectricBsdf::eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
    if (smooth_) return {};
    const std::optional<Connection> c = connect(wo, wi);
    if (!c) return {};
    const float cos_om = dot(wo, c->m), cos_im = dot(wi, c->m);
    const float reflectance = fresnel_dielectric(cos_om, eta_);
    if (same_hemisphere(wo, wi)) return Rgb(reflectance * microfacet_reflection(ggx_, wo, wi, c->m));
    // Walter et al. 2007, eq. 21, with the Jacobian of the refracted half vector folded in.
    const float denominator = cos_im + cos_om / c->eta;
    const float value = (1.0f - reflectance) * ggx_.d(c->m) * ggx_.g2(wo, wi) * std::abs(cos_im * cos_om) /
                        (std::abs(wo.z * wi.z) * denominator * denominator);
    return transmission_scale(c->eta, mode) * value;
}

float DielectricBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (smooth_) return 0;
    const std::optional<Connection> c = connect(wo, wi);
    if (!c) return 0;
    const float cos_om = dot(wo, c->m), cos_im = dot(wi, c->m);
    // sample_rough() reflects with probability F and refracts otherwise.
    const float reflectance = fresnel_dielectric(cos_om, eta_);
    if (same_hemisphere(wo, wi)) return reflectance * microfacet_reflection_pdf(ggx_, wo, c->m);
    const float denominator = cos_im + cos_om / c->eta;
    const float dm_dwi = std::abs(cos_im) / (denominator * denominator);
    return (1.0f - reflectance) * ggx_.visible_normal_pdf(wo, c->m) * dm_dwi;
}

std::optional<BsdfSample> DielectricBsdf::sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                                 TransportMode mode) const {
    if (wo.z == 0) return std::nullopt;
    return smooth_ ? sample_smooth(wo, u_lobe, mode) : sample_rough(wo, u_lobe, u, mode);
}

std::optional<BsdfSample> DielectricBsdf::sample_smooth(const Vec3f& wo, float u_lobe, TransportMode mode) const {
    const float reflectance = fresnel_dielectric(wo.z, eta_);
    BsdfSample sample;
    sample.is_delta = true;
    if (u_lobe < reflectance) {
        sample.weight = Rgb(1.0f);
        sample.wi = mirror_z(-wo);
        sample.pdf = reflectance;
        return sample;
    }
    const float eta_rel = refraction_eta(wo);
    const std::optional<Vec3f> wi = refract(wo, Vec3f(0, 0, std::copysign(1.0f, wo.z)), eta_rel);
    if (!wi) return std::nullopt;  // unreachable: total internal reflection has reflectance 1
    sample.weight = transmission_scale(eta_rel, mode);
    sample.wi = *wi;
    sample.pdf = 1.0f - reflectance;
    sample.is_transmission = true;
    sample.eta = eta_rel;
    return sample;
}

std::optional<BsdfSample> DielectricBsdf::sample_rough(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                                       TransportMode mode) const {
    // A direction the chosen lobe sends to the wrong side is lost: pdf() would take it for the other lobe.
    const Vec3f m = ggx_.sample_visible_normal(wo, u);
    const float cos_om = dot(wo, m);
    if (u_lobe < fresnel_dielectric(cos_om, eta_)) {
        const Vec3f wi = reflect(wo, m);
        if (!same_hemisphere(wo, wi)) return std::nullopt;
        return sample_towards(*this, wo, wi, mode);
    }
    const float eta_rel = refraction_eta(wo);
    const std::optional<Vec3f> wi = refract(wo, std::copysign(1.0f, cos_om) * m, eta_rel);
    if (!wi || wi->z * wo.z >= 0) return std::nullopt;
    return sample_towards(*this, wo, *wi, mode, eta_rel);
}

}  // namespace isotrace
