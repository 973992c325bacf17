#pragma once
// Direction helpers in the local shading frame (z = shading normal, directions point away from the surface).
#include <algorithm>
#include <cmath>
#include <optional>

#include "renderer/math/vec3.h"

namespace isotrace {

inline bool same_hemisphere(const Vec3f& a, const Vec3f& b) { return a.z * b.z > 0; }

// The mirror image of w in the surface plane, for two-sided models that shade on wo's side.
inline Vec3f mirror_z(const Vec3f& w) { return {w.x, w.y, -w.z}; }

// w reflected about the unit normal n (the result points away from the surface like w).
inline Vec3f reflect(const Vec3f& w, const Vec3f& n) { return 2.0f * dot(w, n) * n - w; }

// w refracted through the unit normal n (n on w's side, dot(w, n) > 0) by Snell's law; eta is the IOR on the
// far side over the IOR on w's side. Empty under total internal reflection.
inline std::optional<Vec3f> refract(const Vec3f& w, const Vec3f& n, float eta) {
    const float cos_i = dot(w, n);
    const float sin2_t = std::max(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) return std::nullopt;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    return -w / eta + (cos_i / eta - cos_t) * n;
}

}  // namespace isotrace
