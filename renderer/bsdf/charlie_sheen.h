#pragma once
// Sheen: the retro-reflective glow of cloth and dust, microfibres seen at grazing angles. Estevez and Kulla's
// "Charlie" model (2017, "Production Friendly Microfacet Sheen BRDF"):
//   D(m) = (2 + 1/a) sin(theta_m)^(1/a) / (2 pi),   a = sheen roughness^2 (as glTF's KHR_materials_sheen),
//   f = D(h) / ((1 + Lambda(mu_o) + Lambda(mu_i)) 4 mu_o mu_i)
// with the paper's fitted Lambda and height-correlated masking, without its "terminator softening" (which applies
// to the light's side only and would break reciprocity). Reflection only, upper side (wo.z > 0, wi.z > 0). The
// lobe is broad: models sample it by the cosine.
#include "renderer/math/vec3.h"

namespace isotrace {

// Sheen roughness is raised to this: below it the fitted Lambda lets the lobe reflect more than it receives at
// grazing angles (albedo 1.03 at roughness 0.25, 2.1 at 0.1; at most 0.93 from 0.3 up).
inline constexpr float kMinSheenRoughness = 0.3f;

class CharlieSheen {
public:
    // roughness in [0, 1] (raised to kMinSheenRoughness). Cheap: keeps the table coordinate.
    explicit CharlieSheen(float roughness);

    float d(const Vec3f& m) const;
    // The fitted Smith Lambda at cos theta = mu in (0, 1].
    float lambda(float mu) const;
    // Height-correlated masking and shadowing 1 / (1 + Lambda(mu_o) + Lambda(mu_i)).
    float g2(const Vec3f& wo, const Vec3f& wi) const;
    float eval(const Vec3f& wo, const Vec3f& wi) const;
    // The directional albedo integral of f cos over the hemisphere at cos theta = mu, interpolated in a table over
    // (mu, roughness) built once per process on first use (thread-safe, the same on every run).
    float albedo(float mu) const;

private:
    float inverse_alpha_;
    float fit_[5];  // the fit's coefficients a to e, interpolated at this roughness
    float roughness_coordinate_;
};

}  // namespace isotrace
