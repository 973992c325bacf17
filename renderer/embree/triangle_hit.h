#pragma once
// A hit on one of Embree's own triangles, solved again: where the ray meets the triangle's plane (t) and the
// barycentrics of its second and third corners (u, v), as Embree reports them.
//
// Why: Embree forms t, u and v as products with an approximate reciprocal (rcpps and one Newton step), whose last
// bits differ between CPU makers, so a render of a mesh would differ in its last bits between an Intel and an AMD
// machine. Which triangle a ray hits is decided by Embree's division-free tests, which round alike everywhere; the
// numbers that shade it come from here, in plain IEEE arithmetic. Inline: a render completes one per mesh hit, and
// its latency stands between Embree's answer and the shading.
#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>

#include "renderer/math/vec3.h"

namespace isotrace {

// The vertices and corner indices of a shape traced as Embree triangles (empty for every other shape).
struct TriangleView {
    std::span<const Vec3f> positions;
    std::span<const std::array<std::uint32_t, 3>> triangles;

    bool empty() const { return triangles.empty(); }
};

template <class Real>
struct TriangleSolution {
    Real t = 0, u = 0, v = 0;
    Vec3T<Real> normal;  // (p1 − p0) × (p2 − p0), Embree's Ng: not normalised
};

// Solves origin + t·direction = p0 + u·(p1 − p0) + v·(p2 − p0) by Cramer's rule (the form of Möller and Trumbore,
// "Fast, minimum storage ray/triangle intersection"), in float for a render's hits (whose rays are float) and in
// double for crossing queries (whose rays are double). False where the direction lies in the triangle's plane or the
// triangle is degenerate: then nothing is solved.
template <class Real>
inline bool solve_triangle_hit(const Vec3T<Real>& origin, const Vec3T<Real>& direction, const Vec3T<Real>& p0,
                               const Vec3T<Real>& p1, const Vec3T<Real>& p2, TriangleSolution<Real>& solution) {
    const Vec3T<Real> e1 = p1 - p0, e2 = p2 - p0, s = origin - p0;
    const Vec3T<Real> p = cross(direction, e2), q = cross(s, e1);
    const Real determinant = dot(e1, p);
    if (!(std::abs(determinant) > 0)) return false;
    const Real inverse = 1 / determinant;
    solution = {dot(e2, q) * inverse, dot(s, p) * inverse, dot(direction, q) * inverse, cross(e1, e2)};
    return std::isfinite(solution.t) && std::isfinite(solution.u) && std::isfinite(solution.v);
}

// Replaces Embree's t, u, v and Ng of a hit on triangle hit.primID of `mesh` by the solved ones, for the ray as the
// mesh's own space sees it. u and v are kept within the triangle (rounding may put a hit on an edge a hair outside);
// a hit that cannot be solved keeps Embree's numbers.
inline void resolve_triangle_hit(const TriangleView& mesh, const Vec3f& origin, const Vec3f& direction, RTCHit& hit,
                                 float& t) {
    const std::array<std::uint32_t, 3>& corners = mesh.triangles[hit.primID];
    TriangleSolution<float> solved;
    if (!solve_triangle_hit(origin, direction, mesh.positions[corners[0]], mesh.positions[corners[1]],
                            mesh.positions[corners[2]], solved))
        return;
    float u = std::max(solved.u, 0.0f), v = std::max(solved.v, 0.0f);
    if (u + v > 1) {
        const float sum = u + v;
        u /= sum, v /= sum;
    }
    t = solved.t;
    hit.u = u;
    hit.v = v;
    hit.Ng_x = solved.normal.x;
    hit.Ng_y = solved.normal.y;
    hit.Ng_z = solved.normal.z;
}

}  // namespace isotrace
