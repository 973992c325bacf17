#include "geometry/plane/planar_frame.h"

#include <cmath>

namespace isotrace {

PlanarFrame::PlanarFrame(const Vec3d& origin, const Vec3d& axis_u, const Vec3d& axis_v)
    : origin_(origin), axis_u_(axis_u), axis_v_(axis_v), normal_(normalize(cross(axis_u, axis_v))) {
    // The dual basis within the plane: dual_u is orthogonal to axis_v and the normal, and dual_u·axis_u = 1.
    const Vec3d across_v = cross(axis_v_, normal_), across_u = cross(normal_, axis_u_);
    dual_u_ = across_v / dot(axis_u_, across_v);
    dual_v_ = across_u / dot(axis_v_, across_u);
}

PlanarFrame PlanarFrame::transformed(const Transform& to_world) const {
    PlanarFrame result(to_world.point(origin_), to_world.vector(axis_u_), to_world.vector(axis_v_));
    if (to_world.determinant() < 0) {  // a mirror: u × v turns to the back; keep the mapped normal's side
        result.normal_ = -result.normal_;
    }
    return result;
}

std::optional<double> PlanarFrame::crossing(const Vec3d& line_origin, const Vec3d& direction) const {
    const double approach = dot(normal_, direction);
    if (approach == 0) return std::nullopt;
    const double t = dot(normal_, origin_ - line_origin) / approach;
    if (!std::isfinite(t)) return std::nullopt;
    return t;
}

std::array<Vec3d, 2> tangent_axes(const Vec3d& normal) {
    const Vec3d along_z = cross(normal, Vec3d{0, 0, 1});
    // |normal × z| = sin of the angle to the z axis; below 0.4 (about 24°) the y-based axis is the longer one.
    const Vec3d u = length(along_z) > 0.4 ? normalize(along_z) : normalize(cross(Vec3d{0, 1, 0}, normal));
    return {u, cross(normal, u)};
}

PlanarFrame frame_facing(const Vec3d& origin, const Vec3d& normal, double scale) {
    const auto [u, v] = tangent_axes(normal);
    return PlanarFrame(origin, u * scale, v * scale);
}

}  // namespace isotrace
