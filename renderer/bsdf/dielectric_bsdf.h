#pragma once
// Glass-like interface between the outside (IOR 1, where z points) and an interior of IOR eta: when
// alpha_x = alpha_y = 0 a delta reflection plus a delta refraction chosen with the Fresnel reflectance,
// otherwise GGX microfacet reflection and transmission (Walter et al. 2007). wo.z < 0 means wo is inside.
//
// Transmission in TransportMode::Radiance is divided by eta_rel^2 (eta_rel = IOR on wi's side / IOR on wo's
// side): radiance is compressed on entering a denser medium. The BSDF then obeys the generalised reciprocity
// f(wo, wi) / eta_wo^2 = f(wi, wo) / eta_wi^2 (Veach 1997, eq. 5.14; eta_w = IOR on w's side), and
// f_Importance(wo, wi) = f_Radiance(wi, wo). Reflection is symmetric in both modes.
#include "renderer/bsdf/bsdf.h"
#include "renderer/bsdf/ggx.h"

namespace isotrace {

class DielectricBsdf final {
public:
    // eta > 0, eta != 1 when rough; alphas >= 0, both zero or both positive. The tint multiplies transmission
    // only (a coloured glass body; the surface reflection stays white).
    DielectricBsdf(float eta, float alpha_x, float alpha_y, const Rgb& transmission_tint = Rgb(1.0f));

    Rgb eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode = TransportMode::Radiance) const;
    float pdf(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                     TransportMode mode = TransportMode::Radiance) const;
    bool has_delta_lobe() const { return smooth_; }
    bool is_fully_delta() const { return smooth_; }
    bool chooses_lobe() const { return true; }  // reflection or transmission

private:
    // IOR on the far side over IOR on wo's side.
    float refraction_eta(const Vec3f& wo) const { return wo.z > 0 ? eta_ : 1.0f / eta_; }
    // The microfacet connecting wo and wi (reflection or refraction) and eta_rel (1 for reflection).
    struct Connection {
        Vec3f m;
        float eta;
    };
    std::optional<Connection> connect(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sample_smooth(const Vec3f& wo, float u_lobe, TransportMode mode) const;
    std::optional<BsdfSample> sample_rough(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                           TransportMode mode) const;
    Rgb transmission_scale(float eta_rel, TransportMode mode) const;

    float eta_;
    GgxDistribution ggx_;
    Rgb tint_;
    bool smooth_;
};

}  // namespace isotrace
