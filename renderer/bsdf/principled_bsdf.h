#pragma once
// A "principled" surface: one model whose few artist-facing parameters span metals, plastics, glass, lacquered
// and cloth-like surfaces (after Burley 2012, "Physically-Based Shading at Disney", and the Autodesk Standard
// Surface). Energy-conserving, reciprocal, and importance-sampled as a mixture of its lobes. Seen from outside
// (wo.z > 0) it is a stack of layers, each scaling what lies beneath it by the light it does not reflect:
//
//   f = c f_coat + T_c ( f_sheen + T_s ( m f_metal + (1 - m) ( (1 - t) f_plastic + t f_glass ) ) )
//
//   f_coat    clear GGX coat of IOR 1.5 (Schlick's Fresnel, F0 = 0.04), isotropic, weight c = clearcoat
//   f_sheen   CharlieSheen tinted by sheen * sheen_colour (white sheen: the albedo tables are colourless)
//   f_metal   GGX with Schlick's Fresnel F0 = base_colour, plus Kulla and Conty's multiple-scattering lobe
//             F_ms (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)), F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)):
//             with a white base its albedo is 1 at every roughness
//   f_plastic s f_specular + base_colour (1 - s E(mu_o)) (1 - s E(mu_i)) / (pi (1 - s E_avg)), s = specular:
//             GGX with Schlick's Fresnel, F0 = ((ior - 1) / (ior + 1))^2, over a Lambertian base normalised so
//             that with a white base its albedo is exactly 1
//   f_glass   DielectricBsdf(ior, alpha_x, alpha_y, tint base_colour): rough glass, reflection untinted, with
//             the exact Fresnel term (specular does not weight it)
//
// where E is the GGX albedo of the lobe concerned (GgxAlbedo), T_c = (1 - c E_coat(mu_o)) (1 - c E_coat(mu_i))
// and T_s = (1 - S E_sheen(mu_o)) (1 - S E_sheen(mu_i)) with S the largest channel of the sheen tint. Those
// products are symmetric, so every reflection lobe stays reciprocal; for transmission only the outside direction
// crosses the coat and sheen, so the glass is scaled by T(mu_outside) alone and keeps the dielectric's
// generalised reciprocity. Each layer reflects at most E and passes at most 1 - E, so the albedo never exceeds 1
// (within the tables' error; an anisotropic lobe's E is an upper bound from isotropic tables, see GgxAlbedo).
//
// wo below the surface (wo.z < 0) is inside the object: the glass share g = (1 - m) t sees the dielectric from
// inside (its refraction out is scaled by T(mu_outside)), and the rest, 1 - g, is the response above mirrored
// as for the two-sided models, with t = 0 (there is no glass under it from that side). A surface without
// transmission is therefore exactly two-sided like the others; one with transmission 1 is pure glass from inside.
//
// Roughness 0 makes the metal, specular and glass lobes deltas; clearcoat_roughness 0 the coat. sample() picks a
// lobe with probabilities proportional to estimates of the lobes' albedos at wo (coat, the base's GGX lobe for
// metal and specular together, the glass, and a cosine lobe for sheen, multiple scattering and diffuse), and
// pdf() is the mixture's. Internally alpha_x and alpha_y come from roughness and anisotropy (see
// PrincipledParameters). Member functions as in bsdf.h.
#include "renderer/bsdf/bsdf.h"
#include "renderer/bsdf/charlie_sheen.h"
#include "renderer/bsdf/dielectric_bsdf.h"
#include "renderer/bsdf/ggx.h"
#include "renderer/bsdf/ggx_albedo.h"

namespace isotrace {

// Values outside the stated ranges are clamped into them (NaN to the lower end).
struct PrincipledParameters {
    Rgb base_colour{0.8f};       // each in [0, 1]
    float metallic = 0;          // [0, 1]
    // Perceptual [0, 1], alpha = roughness^2 (roughness_to_alpha); 0 = smooth (delta lobes).
    float roughness = 0.5f;
    // [0, 1]: stretches alpha along the frame's x axis keeping the product alpha_x alpha_y = alpha^2 (Burley
    // 2012, anisotropic_alphas): alpha_x = alpha / k, alpha_y = alpha k with k = sqrt(1 - 0.9 anisotropy), so
    // anisotropy 1 makes the highlight 10 times as long along x as along y.
    float anisotropy = 0;
    float ior = 1.5f;            // dielectric IOR, [1.0001, 100]
    // [0, 1] weight of the dielectric specular reflection; 0 with metallic 0, transmission 0, clearcoat 0,
    // sheen 0 is exactly LambertBsdf(base_colour).
    float specular = 1;
    float transmission = 0;      // [0, 1]: share of the dielectric base that is a rough glass (tinted by base_colour)
    float clearcoat = 0;         // [0, 1] weight of a clear GGX coat (IOR 1.5) on top
    float clearcoat_roughness = 0.03f;  // perceptual [0, 1], as roughness
    float sheen = 0;             // [0, 1]
    Rgb sheen_colour{1.0f};      // each in [0, 1]
    float sheen_roughness = 0.5f;  // [0, 1], raised to kMinSheenRoughness (0.3)
};

// Calls visit(a.p, b.p) for every parameter p above, in order: the one list of them for code that treats them all
// alike (blending parameters, a material's textures of them). a and b may be of any types with members of these
// names.
template <class A, class B, class Visit>
void for_each_principled_parameter(A& a, B& b, Visit&& visit) {
    visit(a.base_colour, b.base_colour);
    visit(a.metallic, b.metallic);
    visit(a.roughness, b.roughness);
    visit(a.anisotropy, b.anisotropy);
    visit(a.ior, b.ior);
    visit(a.specular, b.specular);
    visit(a.transmission, b.transmission);
    visit(a.clearcoat, b.clearcoat);
    visit(a.clearcoat_roughness, b.clearcoat_roughness);
    visit(a.sheen, b.sheen);
    visit(a.sheen_colour, b.sheen_colour);
    visit(a.sheen_roughness, b.sheen_roughness);
}

class PrincipledBsdf final {
public:
    explicit PrincipledBsdf(const PrincipledParameters& parameters);

    Rgb eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode = TransportMode::Radiance) const;
    float pdf(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                     TransportMode mode = TransportMode::Radiance) const;
    bool has_delta_lobe() const { return has_delta_lobe_; }
    bool is_fully_delta() const { return is_fully_delta_; }
    bool chooses_lobe() const { return chooses_lobe_; }

private:
    // The lobes sample() chooses between.
    enum Lobe { kCoat, kBaseSpecular, kCosine, kGlass, kLobeCount };
    using LobeProbabilities = std::array<float, kLobeCount>;
    // The opaque layers' response seen from wo's side: its weight and the base's metal and plastic shares.
    struct View {
        float scale, metal, plastic;
    };
    View view(const Vec3f& wo) const;
    // Non-delta reflection of the opaque layers, wo.z > 0 and wi.z > 0 (mirrored when seen from below).
    Rgb opaque_reflection(const Vec3f& wo, const Vec3f& wi, const View& view) const;
    // The weight of the glass lobe between wo and wi: its share times the coat and sheen's transmittance on
    // each side that is outside.
    float glass_weight(const Vec3f& wo, const Vec3f& wi) const;
    // What the coat and the sheen let through at cos theta = mu (> 0): T_c and T_s for one direction.
    float coat_transmittance(float mu) const;
    float sheen_transmittance(float mu) const;
    LobeProbabilities lobe_probabilities(const Vec3f& wo, const View& view) const;
    DielectricBsdf glass() const;
    // The weight of a delta mirror reflection of wo for the coat or the smooth base (mu = |wo.z|).
    Rgb base_mirror_weight(float mu, const View& view) const;

    Rgb base_colour_;
    Rgb sheen_tint_;        // sheen * sheen_colour
    Rgb multiple_scattering_fresnel_;  // F_ms
    float metallic_, specular_, clearcoat_, eta_;
    float glass_;           // (1 - metallic) transmission
    float plastic_;         // (1 - metallic) (1 - transmission)
    float sheen_max_;       // the sheen tint's largest channel
    float multiple_scattering_scale_;  // 1 / (pi (1 - E_avg)) of the metal, 0 without compensation
    float diffuse_scale_;   // 1 / (pi (1 - specular E_avg)) of the dielectric specular
    GgxDistribution base_ggx_, coat_ggx_;
    float specular_f0_;     // Schlick's F0 of the dielectric specular
    GgxAlbedo base_albedo_, coat_albedo_;  // of the metal and specular lobes, and of the coat
    CharlieSheen sheen_;
    bool base_smooth_, coat_smooth_;
    bool has_delta_lobe_, is_fully_delta_, chooses_lobe_;
    bool plain_diffuse_;    // only the cosine lobe, unscaled: the model is LambertBsdf(base_colour_) and samples as it
};

}  // namespace isotrace
