#pragma once
// A plane with an affine parametrisation p = origin + s·axis_u + t·axis_v and a front side: the frame the plane,
// the disk and the rectangle share. Crossings and coordinates are computed in double; an affine map carries the
// frame to the exact image of the surface (a disk becomes an ellipse, a rectangle a parallelogram), so these
// shapes bake every placement.
#include <array>
#include <optional>

#include "renderer/math/transform.h"
#include "renderer/math/vec3.h"

namespace isotrace {

class PlanarFrame {
public:
    PlanarFrame() = default;
    // `axis_u` and `axis_v` independent; the front is the side axis_u × axis_v points to.
    PlanarFrame(const Vec3d& origin, const Vec3d& axis_u, const Vec3d& axis_v);

    // The image under an affine map. The front stays the side the mapped normal points to (normals map by the
    // inverse transpose), also through a mirror.
    PlanarFrame transformed(const Transform& to_world) const;

    // The parameter where the line origin + t·direction (direction of any length) crosses the plane; nullopt for a
    // line parallel to it, also one lying in it (a grazing ray misses).
    std::optional<double> crossing(const Vec3d& line_origin, const Vec3d& direction) const;
    // (s, t) of a point of the plane (of its projection along the normal, for any point).
    std::array<double, 2> coordinates(const Vec3d& p) const { return {dot(p - origin_, dual_u_), dot(p - origin_, dual_v_)}; }
    Vec3d point(double s, double t) const { return origin_ + axis_u_ * s + axis_v_ * t; }
    // Signed distance of p from the plane, positive on the front.
    double height(const Vec3d& p) const { return dot(p - origin_, normal_); }

    const Vec3d& origin() const { return origin_; }
    const Vec3d& axis_u() const { return axis_u_; }
    const Vec3d& axis_v() const { return axis_v_; }
    const Vec3d& normal() const { return normal_; }  // unit, on the front
    // |axis_u × axis_v|: the area of the unit square of (s, t).
    double cell_area() const { return length(cross(axis_u_, axis_v_)); }

private:
    Vec3d origin_, axis_u_{1, 0, 0}, axis_v_{0, 0, -1}, normal_{0, 1, 0};
    Vec3d dual_u_{1, 0, 0}, dual_v_{0, 0, -1};  // s = (p − origin)·dual_u, t = (p − origin)·dual_v
};

// The unit tangent axes the plane and the disk give a surface facing `normal` (unit): u along normal × z (the x
// axis when the normal is +y), or along y × normal when the normal lies within about 25° of the z axis, where
// normal × z is short; v = normal × u, so that u × v is the normal.
std::array<Vec3d, 2> tangent_axes(const Vec3d& normal);

// The frame at `origin` facing `normal` (unit) whose axes are tangent_axes(normal) of length `scale`.
PlanarFrame frame_facing(const Vec3d& origin, const Vec3d& normal, double scale);

}  // namespace isotrace
