#include "renderer/bsdf/microfacet.h"

#include <cmath>

namespace isotrace {

std::optional<Vec3f> microfacet_normal(const Vec3f& wo, const Vec3f& wi, float eta) {
    if (wo.z == 0 || wi.z == 0) return std::nullopt;
    Vec3f m = wo + eta * wi;
    const float length2 = dot(m, m);
    if (!(length2 > 0)) return std::nullopt;
    m = m / std::sqrt(length2);
    if (m.z < 0) m = -m;
    // Each direction must see the microfacet's front from its own side of the macrosurface.
    if (dot(m, wo) * wo.z <= 0 || dot(m, wi) * wi.z <= 0) return std::nullopt;
    return m;
}

float microfacet_reflection(const GgxDistribution& ggx, const Vec3f& wo, const Vec3f& wi, const Vec3f& m) {
    return ggx.d(m) * ggx.g2(wo, wi) / (4.0f * std::abs(wo.z) * std::abs(wi.z));
}

float microfacet_reflection_pdf(const GgxDistribution& ggx, const Vec3f& wo, const Vec3f& m) {
    return ggx.visible_normal_pdf(wo, m) / (4.0f * std::abs(dot(wo, m)));
}

}  // namespace isotrace
