#include "geometry/rectangle/spherical_rectangle.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace isotrace {
namespace {

// The angle between two unit vectors, from their dot product clamped against rounding.
double angle_between(const Vec3d& a, const Vec3d& b) { return std::acos(std::clamp(dot(a, b), -1.0, 1.0)); }

}  // namespace

std::optional<SphericalRectangle> SphericalRectangle::make(const Vec3d& reference, const Vec3d& corner,
                                                           const Vec3d& edge_x, const Vec3d& edge_y) {
    const double width = length(edge_x), height = length(edge_y);
    if (!(width > 0) || !(height > 0)) return std::nullopt;
    const Vec3d x = edge_x / width, y = edge_y / height;
    Vec3d z = cross(x, y);
    const Vec3d d = corner - reference;
    SphericalRectangle r;
    r.z0_ = dot(d, z);
    if (r.z0_ > 0) {  // the frame's z points away from the rectangle
        z = -z;
        r.z0_ = -r.z0_;
    }
    if (!(r.z0_ < 0)) return std::nullopt;  // in the plane: no solid angle
    r.x0_ = dot(d, x);
    r.y0_ = dot(d, y);
    r.x1_ = r.x0_ + width;
    r.y1_ = r.y0_ + height;
    // The normals of the planes through the reference and each edge, and the rectangle's internal angles.
    const Vec3d v00(r.x0_, r.y0_, r.z0_), v01(r.x0_, r.y1_, r.z0_), v10(r.x1_, r.y0_, r.z0_), v11(r.x1_, r.y1_, r.z0_);
    const Vec3d n0 = normalize(cross(v00, v10)), n1 = normalize(cross(v10, v11));
    const Vec3d n2 = normalize(cross(v11, v01)), n3 = normalize(cross(v01, v00));
    const double g0 = angle_between(-n0, n1), g1 = angle_between(-n1, n2);
    const double g2 = angle_between(-n2, n3), g3 = angle_between(-n3, n0);
    r.solid_angle_ = g0 + g1 + g2 + g3 - 2 * std::numbers::pi;
    if (!(r.solid_angle_ >= kMinSolidAngle)) return std::nullopt;  // also NaN
    r.b0_ = n0.z;
    r.b1_ = n2.z;
    r.k_ = 2 * std::numbers::pi - g2 - g3;
    return r;
}

std::array<double, 2> SphericalRectangle::sample(std::array<double, 2> u) const {
    // u[0] picks the sub-rectangle [x0, xu] whose solid angle is u[0]·Ω, u[1] the point along y in its column.
    const double au = u[0] * solid_angle_ + k_;
    const double fu = (std::cos(au) * b0_ - b1_) / std::sin(au);
    const double cu = std::clamp(std::copysign(1 / std::sqrt(fu * fu + b0_ * b0_), fu), -1.0, 1.0);
    double xu = -(cu * z0_) / std::sqrt(std::max(0.0, 1 - cu * cu));
    xu = std::isnan(xu) ? x0_ : std::clamp(xu, x0_, x1_);
    const double dd = std::sqrt(xu * xu + z0_ * z0_);
    const double h0 = y0_ / std::sqrt(dd * dd + y0_ * y0_), h1 = y1_ / std::sqrt(dd * dd + y1_ * y1_);
    const double hv = h0 + u[1] * (h1 - h0), hv_squared = hv * hv;
    const double yv = hv_squared < 1 - 1e-12 ? hv * dd / std::sqrt(1 - hv_squared) : y1_;
    return {(xu - x0_) / (x1_ - x0_), std::clamp((yv - y0_) / (y1_ - y0_), 0.0, 1.0)};
}

}  // namespace isotrace
