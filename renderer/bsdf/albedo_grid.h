#pragma once
// The grid the albedo tables (GgxAlbedo, CharlieSheen) are tabulated on and interpolated in, and the quadrature
// that fills them. Along cos theta the nodes are mu = t^2 for t evenly spaced, dense near grazing where albedos
// change fastest; other coordinates are evenly spaced. Values are linear between nodes (in t along mu).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "renderer/math/vec3.h"

namespace isotrace {

// The node's mu; mu = 0 itself is degenerate (no direction sees the surface) and stands in for a tiny mu.
inline float albedo_grid_mu(int node, int nodes) {
    const float t = float(node) / float(nodes - 1);
    return std::max(t * t, 1e-4f);
}

// A continuous coordinate in [0, nodes - 1] (clamped, NaN to 0: it becomes an index): the cell's lower node and
// the weight of its upper node.
struct AlbedoGridCell {
    int node;
    float fraction;
};

inline AlbedoGridCell albedo_grid_cell(float coordinate, int nodes) {
    const float inside = coordinate > 0 ? std::min(coordinate, float(nodes - 1)) : 0.0f;
    const int node = std::min(int(inside), nodes - 2);
    return {node, inside - float(node)};
}

inline AlbedoGridCell albedo_grid_mu_cell(float mu, int nodes) {
    return albedo_grid_cell(std::sqrt(mu > 0 ? std::min(mu, 1.0f) : 0.0f) * float(nodes - 1), nodes);
}

inline float lerp(float a, float b, float t) { return a + t * (b - a); }

// The 16-point Gauss-Legendre rule on [0, 1].
struct GaussLegendre {
    std::array<double, 16> x, w;
};
const GaussLegendre& gauss_legendre();

// An isotropic microfacet distribution for the quadrature, given by the cumulative distribution of D(m) m.z in
// theta_m: u(theta) in [0, 1] and its inverse theta(u).
struct MicrofacetCdf {
    std::function<double(double)> u_of_theta, theta_of_u;
};

// Visits quadrature nodes m with weights w such that sum w g(m) approximates the integral of g(m) D(m) m.z dm over
// the normals that reflect wo (in the xz plane, wo.z > 0) above the horizon, for g symmetric about that plane.
// Gauss-Legendre in u (the distribution's own measure, so narrow lobes cost nothing more; see the .cpp for the
// substitution) up to the horizon cut, which is analytic: reflect(wo, m).z > 0 exactly when
// 2 theta_m < delta + pi / 2 with tan delta = sin theta_o cos phi / cos theta_o. Gauss-Legendre in phi as well,
// split at pi / 2, where the cut turns fastest for grazing wo.
void visit_reflecting_normals(const Vec3f& wo, const MicrofacetCdf& cdf,
                              const std::function<void(const Vec3f& m, double weight)>& visit);

}  // namespace isotrace
