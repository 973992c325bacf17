#pragma once
// Direction helpers in the local shading frame (z = shading normal, directions point away from the surface).
#include <algorithm>
#include <cmath>
#include <optional>

#include "renderer/math/vec3.h"

namespace isotrace {

// World <-> local shading frame: z is the shading normal n, x the given tangent made perpendicular to n (a right-
// handed frame); a zero tangent (or one along n) lets orthonormal_basis choose x, for isotropic models.
struct ShadingFrame {
    Vec3f tangent, bitangent, normal;

    ShadingFrame(const Vec3f& n, const Vec3f& t) : normal(n) {
        // Most hits have no tangent: its projection would be zero, and orthonormal_basis is what it would lead to.
        if (t.x == 0 && t.y == 0 && t.z == 0) {
            orthonormal_basis(n, tangent, bitangent);
            return;
        }
        const Vec3f along = t - n * dot(n, t);
        const float length2 = dot(along, along);
        if (length2 > 1e-12f) {
            tangent = along / std::sqrt(length2);
            bitangent = cross(n, tangent);
        } else {
            orthonormal_basis(n, tangent, bitangent);
        }
    }
    Vec3f to_local(const Vec3f& w) const { return {dot(w, tangent), dot(w, bitangent), dot(w, normal)}; }
    Vec3f to_world(const Vec3f& w) const { return tangent * w.x + bitangent * w.y + normal * w.z; }
};

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
