#include "renderer/bsdf/ggx.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

Vec3f upper_side(const Vec3f& w) { return w.z < 0 ? -w : w; }

}  // namespace

float roughness_to_alpha(float roughness) {
    return roughness * roughness;
}

GgxDistribution::GgxDistribution(float alpha_x, float alpha_y)
    : alpha_x_(std::max(alpha_x, kMinGgxAlpha)), alpha_y_(std::max(alpha_y, kMinGgxAlpha)) {}

float GgxDistribution::d(const Vec3f& m) const {
    if (m.z <= 0) return 0;
    // The ellipsoid form 1 / (pi ax ay (x^2/ax^2 + y^2/ay^2 + z^2)^2) avoids tan(theta), infinite at grazing m.
    const float x = m.x / alpha_x_, y = m.y / alpha_y_;
    const float s = x * x + y * y + m.z * m.z;
    return 1.0f / (kPi * alpha_x_ * alpha_y_ * s * s);
}

float GgxDistribution::lambda(const Vec3f& w) const {
    const float ax = alpha_x_ * w.x, ay = alpha_y_ * w.y;
    const float alpha2_tan2 = (ax * ax + ay * ay) / (w.z * w.z);  // +inf at w.z = 0 gives Lambda = inf, G1 = 0
    return 0.5f * (std::sqrt(1.0f + alpha2_tan2) - 1.0f);
}

float GgxDistribution::g1(const Vec3f& w) const {
    return 1.0f / (1.0f + lambda(w));
}

float GgxDistribution::g2(const Vec3f& wo, const Vec3f& wi) const {
    return 1.0f / (1.0f + lambda(wo) + lambda(wi));
}

Vec3f GgxDistribution::sample_visible_normal(const Vec3f& w, std::array<float, 2> u) const {
    // Stretch the view so the microsurface becomes a hemisphere of unit roughness, sample the visible part of
    // that hemisphere as a disk warped towards the view, then unstretch the normal.
    const Vec3f v = upper_side(w);
    const Vec3f view = normalize(Vec3f(alpha_x_ * v.x, alpha_y_ * v.y, v.z));
    const float xy_length2 = view.x * view.x + view.y * view.y;
    const Vec3f t1 = xy_length2 > 0 ? Vec3f(-view.y, view.x, 0.0f) / std::sqrt(xy_length2) : Vec3f(1, 0, 0);
    const Vec3f t2 = cross(view, t1);

    auto [p1, p2] = square_to_uniform_disk_concentric(u);
    // The half of the disk hidden behind the hemisphere's silhouette shrinks as the view tilts.
    const float s = 0.5f * (1.0f + view.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    const Vec3f n = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * view;
    return normalize(Vec3f(alpha_x_ * n.x, alpha_y_ * n.y, std::max(1e-6f, n.z)));
}

float GgxDistribution::visible_normal_pdf(const Vec3f& w, const Vec3f& m) const {
    if (w.z == 0) return 0;
    const float cos_wm = dot(upper_side(w), m);
    if (cos_wm <= 0) return 0;
    return g1(w) * cos_wm * d(m) / std::abs(w.z);
}

}  // namespace isotrace
