#pragma once
// Directional albedo E(mu) = integral of f cos over the hemisphere of the isotropic GGX reflection lobe
// F(wo.m) D G2 / (4 mu_o mu_i) with Schlick's Fresnel F = F0 + (1 - F0) (1 - wo.m)^5, seen from cos theta = mu,
// and its cosine-weighted average 2 * integral of E(mu) mu dmu. Layered models scale what lies beneath a lobe by
// 1 - E (the share it does not reflect) and compensate the energy single scattering loses with 1 - E (Kulla and
// Conty 2017, "Revisiting Physically Based Shading at Imageworks"). E is linear in F0, so two tables over
// (mu, roughness) serve every F0: F = 1 and F = (1 - wo.m)^5. They are built once per process on first use
// (function-local static: thread-safe, and the same on every run).
#include <array>

#include "renderer/math/vec3.h"

namespace isotrace {

// Burley's anisotropic alphas (2012): alpha = roughness^2 (roughness_to_alpha) stretched along x and narrowed
// along y keeping alpha_x alpha_y = alpha^2: alpha_x = alpha / k, alpha_y = alpha k, k = sqrt(1 - 0.9 anisotropy).
// Anisotropy in [0, 1]: 1 makes the highlight 10 times as long along x as along y (alpha_x up to 3.16).
std::array<float, 2> anisotropic_alphas(float roughness, float anisotropy);

class GgxAlbedo {
public:
    // The lobe of anisotropic_alphas(roughness, anisotropy); roughness 0 is the smooth mirror, whose albedo is
    // F(mu). Cheap: reads the averages from a table and keeps the coordinates.
    GgxAlbedo(float roughness, float anisotropy);

    // E(w) for the reflectance f0 at normal incidence (1: a perfect reflector), w on the upper side; for the
    // smooth mirror the exact Schlick reflectance rather than the table's interpolation of it. An anisotropic
    // lobe's albedo depends on w's azimuth too, which the isotropic tables only bound: it is taken as the larger
    // of the tables' values at the geometric mean alpha sqrt(alpha_x alpha_y) and at the alpha w projects
    // (sqrt(alpha_x^2 cos^2 phi + alpha_y^2 sin^2 phi)), which errs on the side of reflecting too much, so that
    // a layer scaled by 1 - E receives too little rather than too much.
    float albedo(const Vec3f& w, float f0) const;
    // The same for an isotropic lobe, which depends on mu = cos theta only (in [0, 1], clamped).
    float albedo(float mu, float f0) const;
    // (1 / pi) integral of E mu over the hemisphere: the share of cosine-distributed light reflected (tabulated
    // over roughness and anisotropy as well).
    float average(float f0) const { return f0 * average_[0] + (1.0f - f0) * average_[1]; }

private:
    float roughness_coordinate_;         // of the geometric mean alpha
    float alpha_x2_ = 0, alpha_y2_ = 0;  // squared, when anisotropic
    bool anisotropic_;
    float average_[2];  // of the two tables: F = 1 and F = (1 - wo.m)^5
};

}  // namespace isotrace
