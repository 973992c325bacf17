#include "renderer/bsdf/principled_bsdf.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "renderer/bsdf/fresnel.h"
#include "renderer/bsdf/lambert_bsdf.h"
#include "renderer/bsdf/microfacet.h"
#include "renderer/bsdf/shading_frame.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

constexpr float kCoatF0 = 0.04f;  // IOR 1.5
constexpr float kMinIor = 1.0001f, kMaxIor = 100.0f;
constexpr float kInvPi = std::numbers::inv_pi_v<float>;

float unit(float v) { return v > 0 ? std::min(v, 1.0f) : 0.0f; }
Rgb unit(const Rgb& c) { return {unit(c.r), unit(c.g), unit(c.b)}; }
float mean(const Rgb& c) { return (c.r + c.g + c.b) * (1.0f / 3.0f); }

std::array<float, 2> base_alphas(const PrincipledParameters& p) {
    return anisotropic_alphas(unit(p.roughness), unit(p.anisotropy));
}

float coat_alpha(const PrincipledParameters& p) { return roughness_to_alpha(unit(p.clearcoat_roughness)); }

// Kulla and Conty's Fresnel term of the multiple-scattering lobe: of the energy single scattering loses, the
// share that leaves after any number of further bounces, each reflecting F_avg.
Rgb multiple_scattering_fresnel(const Rgb& f0, float average_albedo) {
    const Rgb f = average_fresnel_schlick(f0);
    const auto channel = [average_albedo](float f_avg) {
        return f_avg * f_avg * average_albedo / (1.0f - f_avg * (1.0f - average_albedo));
    };
    return {channel(f.r), channel(f.g), channel(f.b)};
}

Vec3f mirror_direction(const Vec3f& wo) { return mirror_z(-wo); }

BsdfSample delta_sample(const Vec3f& wi, const Rgb& value, float probability) {
    BsdfSample sample;
    sample.weight = value * (1.0f / probability);
    sample.wi = wi;
    sample.pdf = probability;
    sample.is_delta = true;
    return sample;
}

}  // namespace

PrincipledBsdf::PrincipledBsdf(const PrincipledParameters& p)
    : base_colour_(unit(p.base_colour)),
      sheen_tint_(unit(p.sheen_colour) * unit(p.sheen)),
      metallic_(unit(p.metallic)),
      specular_(unit(p.specular)),
      clearcoat_(unit(p.clearcoat)),
      eta_(p.ior > kMinIor ? std::min(p.ior, kMaxIor) : kMinIor),
      glass_((1.0f - metallic_) * unit(p.transmission)),
      plastic_((1.0f - metallic_) * (1.0f - unit(p.transmission))),
      sheen_max_(sheen_tint_.max()),
      base_ggx_(base_alphas(p)[0], base_alphas(p)[1]),
      coat_ggx_(coat_alpha(p), coat_alpha(p)),
      specular_f0_(((eta_ - 1.0f) / (eta_ + 1.0f)) * ((eta_ - 1.0f) / (eta_ + 1.0f))),
      base_albedo_(unit(p.roughness), unit(p.anisotropy)),
      coat_albedo_(unit(p.clearcoat_roughness), 0.0f),
      sheen_(p.sheen_roughness),
      base_smooth_(unit(p.roughness) == 0),
      coat_smooth_(unit(p.clearcoat_roughness) == 0) {
    // 1 - E_avg vanishes with the roughness, and so does the loss it compensates.
    const float metal_loss = 1.0f - base_albedo_.average(1.0f);
    multiple_scattering_scale_ = !base_smooth_ && metal_loss > 1e-6f ? kInvPi / metal_loss : 0.0f;
    multiple_scattering_fresnel_ = multiple_scattering_fresnel(base_colour_, base_albedo_.average(1.0f));
    diffuse_scale_ = kInvPi / (1.0f - specular_ * base_albedo_.average(specular_f0_));

    // Which lobes exist in some view (the plastic also from inside when part of the base is metal).
    const float transmission = unit(p.transmission);
    const bool coat_on = clearcoat_ > 0, metal_on = metallic_ > 0, glass_on = glass_ > 0;
    const bool plastic_on = metallic_ < 1 && (transmission < 1 || metal_on);
    const bool base_on = metal_on || (plastic_on && specular_ > 0);
    const bool cosine_on = sheen_max_ > 0 || plastic_on || (metal_on && multiple_scattering_scale_ > 0);
    has_delta_lobe_ = (coat_on && coat_smooth_) || (base_smooth_ && (base_on || glass_on));
    is_fully_delta_ = !((coat_on && !coat_smooth_) || cosine_on || (!base_smooth_ && (base_on || glass_on)));
    chooses_lobe_ = glass_on || int(coat_on) + int(base_on) + int(cosine_on) > 1;
    plain_diffuse_ = !coat_on && !base_on && !glass_on && sheen_max_ == 0;
}

PrincipledBsdf::View PrincipledBsdf::view(const Vec3f& wo) const {
    if (wo.z > 0) return {1.0f, metallic_, plastic_};
    return {1.0f - glass_, metallic_, 1.0f - metallic_};
}

float PrincipledBsdf::coat_transmittance(float mu) const {
    return clearcoat_ > 0 ? 1.0f - clearcoat_ * coat_albedo_.albedo(mu, kCoatF0) : 1.0f;
}

float PrincipledBsdf::sheen_transmittance(float mu) const {
    return sheen_max_ > 0 ? 1.0f - sheen_max_ * sheen_.albedo(mu) : 1.0f;
}

float PrincipledBsdf::glass_weight(const Vec3f& wo, const Vec3f& wi) const {
    const auto outside = [this](float z) { return z > 0 ? coat_transmittance(z) * sheen_transmittance(z) : 1.0f; };
    return glass_ * outside(wo.z) * outside(wi.z);
}

DielectricBsdf PrincipledBsdf::glass() const {
    if (base_smooth_) return {eta_, 0.0f, 0.0f, base_colour_};
    return {eta_, base_ggx_.alpha_x(), base_ggx_.alpha_y(), base_colour_};
}

Rgb PrincipledBsdf::opaque_reflection(const Vec3f& wo, const Vec3f& wi, const View& v) const {
    const bool rough_coat = clearcoat_ > 0 && !coat_smooth_;
    const float specular = v.plastic * specular_;
    const bool rough_base = !base_smooth_ && (v.metal > 0 || specular > 0);
    const std::optional<Vec3f> h =
        rough_coat || rough_base ? microfacet_normal(wo, wi, 1.0f) : std::optional<Vec3f>();
    Rgb f;
    if (rough_coat && h) {
        f += Rgb(clearcoat_ * fresnel_schlick(dot(wo, *h), kCoatF0) * microfacet_reflection(coat_ggx_, wo, wi, *h));
    }
    Rgb under;
    if (sheen_max_ > 0) under += sheen_tint_ * sheen_.eval(wo, wi);
    Rgb base;
    if (rough_base && h) {
        const float lobe = microfacet_reflection(base_ggx_, wo, wi, *h);
        const float cos_oh = dot(wo, *h);
        if (v.metal > 0) base += fresnel_schlick(cos_oh, base_colour_) * (v.metal * lobe);
        if (specular > 0) base += Rgb(specular * fresnel_schlick(cos_oh, specular_f0_) * lobe);
    }
    if (v.metal > 0 && multiple_scattering_scale_ > 0) {
        const float loss = (1.0f - base_albedo_.albedo(wo, 1.0f)) * (1.0f - base_albedo_.albedo(wi, 1.0f));
        base += multiple_scattering_fresnel_ * (v.metal * loss * multiple_scattering_scale_);
    }
    if (v.plastic > 0) {
        const float passed = (1.0f - specular_ * base_albedo_.albedo(wo, specular_f0_)) *
                             (1.0f - specular_ * base_albedo_.albedo(wi, specular_f0_));
        base += base_colour_ * (v.plastic * passed * diffuse_scale_);
    }
    under += base * (sheen_transmittance(wo.z) * sheen_transmittance(wi.z));
    f += under * (coat_transmittance(wo.z) * coat_transmittance(wi.z));
    return f * v.scale;
}

Rgb PrincipledBsdf::eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
    if (wo.z == 0 || wi.z == 0) return {};
    Rgb f;
    if (same_hemisphere(wo, wi)) {
        const View v = view(wo);
        if (v.scale > 0) f = wo.z > 0 ? opaque_reflection(wo, wi, v) : opaque_reflection(mirror_z(wo), mirror_z(wi), v);
    }
    if (glass_ > 0 && !base_smooth_) f += glass().eval(wo, wi, mode) * glass_weight(wo, wi);
    return f;
}

PrincipledBsdf::LobeProbabilities PrincipledBsdf::lobe_probabilities(const Vec3f& wo, const View& v) const {
    const Vec3f o = wo.z > 0 ? wo : mirror_z(wo);
    const float mu = o.z;
    LobeProbabilities e{};  // estimated albedos first
    if (v.scale > 0) {
        const float below_coat = coat_transmittance(mu), below_sheen = below_coat * sheen_transmittance(mu);
        if (clearcoat_ > 0) e[kCoat] = clearcoat_ * coat_albedo_.albedo(mu, kCoatF0);
        if (sheen_max_ > 0) e[kCosine] += below_coat * mean(sheen_tint_) * sheen_.albedo(mu);
        if (v.metal > 0) {
            const float metal = base_albedo_.albedo(o, 1.0f);
            e[kBaseSpecular] += below_sheen * v.metal * mean(fresnel_schlick(mu, base_colour_)) * metal;
            if (multiple_scattering_scale_ > 0) {
                e[kCosine] += below_sheen * v.metal * mean(multiple_scattering_fresnel_) * (1.0f - metal);
            }
        }
        if (v.plastic > 0) {
            const float specular = specular_ * base_albedo_.albedo(o, specular_f0_);
            e[kBaseSpecular] += below_sheen * v.plastic * specular;
            e[kCosine] += below_sheen * v.plastic * mean(base_colour_) * (1.0f - specular);
        }
        for (float* share : {&e[kCoat], &e[kBaseSpecular], &e[kCosine]}) *share *= v.scale;
    }
    if (glass_ > 0) {
        const float reflectance = fresnel_dielectric(wo.z, eta_);
        const float passed = wo.z > 0 ? coat_transmittance(mu) * sheen_transmittance(mu) : 1.0f;
        e[kGlass] = glass_ * passed * (reflectance + (1.0f - reflectance) * mean(base_colour_));
    }
    const float total = e[kCoat] + e[kBaseSpecular] + e[kCosine] + e[kGlass];
    // Nothing reflects (a black surface): the cosine lobe samples, as a black LambertBsdf would.
    if (!(total > 0)) return {0.0f, 0.0f, 1.0f, 0.0f};
    for (float& share : e) share /= total;
    return e;
}

float PrincipledBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (wo.z == 0 || wi.z == 0) return 0;
    const View v = view(wo);
    const LobeProbabilities p = lobe_probabilities(wo, v);
    float pdf = 0;
    if (p[kGlass] > 0 && !base_smooth_) pdf += p[kGlass] * glass().pdf(wo, wi);
    if (!same_hemisphere(wo, wi)) return pdf;
    const Vec3f o = wo.z > 0 ? wo : mirror_z(wo), i = wo.z > 0 ? wi : mirror_z(wi);
    const bool rough_coat = p[kCoat] > 0 && !coat_smooth_, rough_base = p[kBaseSpecular] > 0 && !base_smooth_;
    if (rough_coat || rough_base) {
        if (const std::optional<Vec3f> h = microfacet_normal(o, i, 1.0f)) {
            if (rough_coat) pdf += p[kCoat] * microfacet_reflection_pdf(coat_ggx_, o, *h);
            if (rough_base) pdf += p[kBaseSpecular] * microfacet_reflection_pdf(base_ggx_, o, *h);
        }
    }
    if (p[kCosine] > 0) pdf += p[kCosine] * square_to_cosine_hemisphere_pdf(i);
    return pdf;
}

Rgb PrincipledBsdf::base_mirror_weight(float mu, const View& v) const {
    const float passed = coat_transmittance(mu) * sheen_transmittance(mu);
    Rgb reflectance = Rgb(v.plastic * specular_ * fresnel_schlick(mu, specular_f0_));
    if (v.metal > 0) reflectance += fresnel_schlick(mu, base_colour_) * v.metal;
    return reflectance * (v.scale * passed * passed);
}

std::optional<BsdfSample> PrincipledBsdf::sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                                 TransportMode mode) const {
    if (wo.z == 0) return std::nullopt;
    if (plain_diffuse_) return LambertBsdf(base_colour_).sample(wo, u_lobe, u);  // its weight, the colour itself
    const View v = view(wo);
    const LobeProbabilities p = lobe_probabilities(wo, v);
    // The lobe whose interval of [0, 1) holds u_lobe; rounding past the last interval falls in the last lobe.
    int lobe = kLobeCount - 1;
    while (lobe > 0 && !(p[lobe] > 0)) --lobe;
    float below = 0;
    for (int k = 0; k < lobe; ++k) {
        if (u_lobe < below + p[k]) {
            lobe = k;
            break;
        }
        below += p[k];
    }

    const bool inside = wo.z < 0;
    const Vec3f o = inside ? mirror_z(wo) : wo;
    // An upper-side direction back on wo's side; lost when it fell below the horizon.
    const auto towards = [&](const Vec3f& wi_upper) -> std::optional<BsdfSample> {
        if (!(wi_upper.z > 0)) return std::nullopt;
        return sample_towards(*this, wo, inside ? mirror_z(wi_upper) : wi_upper, mode);
    };
    switch (lobe) {
    case kCoat:
        if (coat_smooth_) {
            const Rgb value(v.scale * clearcoat_ * fresnel_schlick(o.z, kCoatF0));
            return delta_sample(mirror_direction(wo), value, p[kCoat]);
        }
        return towards(reflect(o, coat_ggx_.sample_visible_normal(o, u)));
    case kBaseSpecular:
        if (base_smooth_) return delta_sample(mirror_direction(wo), base_mirror_weight(o.z, v), p[kBaseSpecular]);
        return towards(reflect(o, base_ggx_.sample_visible_normal(o, u)));
    case kCosine:
        return towards(square_to_cosine_hemisphere(u));
    default: {
        const float u_glass = std::min((u_lobe - below) / p[kGlass], 1.0f - std::numeric_limits<float>::epsilon() / 2);
        std::optional<BsdfSample> s = glass().sample(wo, std::max(u_glass, 0.0f), u, mode);
        if (!s) return std::nullopt;
        if (!s->is_delta) return sample_towards(*this, wo, s->wi, mode, s->eta);
        s->weight = s->weight * (glass_weight(wo, s->wi) / p[kGlass]);
        s->pdf *= p[kGlass];
        return s;
    }
    }
}

}  // namespace isotrace
