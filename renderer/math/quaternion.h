#pragma once
// Quaternions for orientations (sweep key sections, metacube frames): q = w + (x, y, z); a unit q rotates v to
// q·v·q̄. They are also the control points of the sweep's orientation curve (a B-spline in R⁴), hence the
// vector-space operators.
#include <cmath>

#include "renderer/math/vec3.h"

namespace isotrace {

struct Quaternion {
    double w = 0, x = 0, y = 0, z = 0;

    static Quaternion identity() { return {1, 0, 0, 0}; }
    // Rotation by `degrees` about `axis` (any length > 0).
    static Quaternion from_axis_angle(const Vec3d& axis, double degrees);
    // The rotation taking the x, y and z axes to the given orthonormal right-handed axes (Shepperd's method).
    static Quaternion from_axes(const Vec3d& x, const Vec3d& y, const Vec3d& z);

    Vec3d vector() const { return {x, y, z}; }
    Quaternion conjugate() const { return {w, -x, -y, -z}; }
    double norm() const { return std::sqrt(w * w + x * x + y * y + z * z); }
    bool is_finite() const { return std::isfinite(w) && std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }

    // The rotated images of the x, y and z axes (the columns of the rotation matrix); q must be unit.
    Vec3d axis_x() const { return {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)}; }
    Vec3d axis_y() const { return {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)}; }
    Vec3d axis_z() const { return {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}; }
    Vec3d rotate(const Vec3d& v) const { return axis_x() * v.x + axis_y() * v.y + axis_z() * v.z; }
    Vec3d rotate_back(const Vec3d& v) const { return {dot(axis_x(), v), dot(axis_y(), v), dot(axis_z(), v)}; }
};

inline Quaternion operator+(const Quaternion& a, const Quaternion& b) { return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Quaternion operator-(const Quaternion& a, const Quaternion& b) { return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Quaternion operator*(double s, const Quaternion& a) { return {s * a.w, s * a.x, s * a.y, s * a.z}; }
inline double dot(const Quaternion& a, const Quaternion& b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }
// Hamilton product: (a·b) rotates by b first, then by a.
inline Quaternion operator*(const Quaternion& a, const Quaternion& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
inline Quaternion normalize(const Quaternion& q) { return (1 / q.norm()) * q; }

inline Quaternion Quaternion::from_axis_angle(const Vec3d& axis, double degrees) {
    const double half = degrees * (M_PI / 360);
    const Vec3d a = normalize(axis) * std::sin(half);
    return {std::cos(half), a.x, a.y, a.z};
}

inline Quaternion Quaternion::from_axes(const Vec3d& x, const Vec3d& y, const Vec3d& z) {
    // Matrix entries m_rc with columns x, y, z; pick the largest of 4w², 4x², 4y², 4z² to divide by.
    const double trace = x.x + y.y + z.z;
    Quaternion q;
    if (trace > 0) {
        const double s = 2 * std::sqrt(1 + trace);
        q = {s / 4, (y.z - z.y) / s, (z.x - x.z) / s, (x.y - y.x) / s};
    } else if (x.x > y.y && x.x > z.z) {
        const double s = 2 * std::sqrt(1 + x.x - y.y - z.z);
        q = {(y.z - z.y) / s, s / 4, (y.x + x.y) / s, (z.x + x.z) / s};
    } else if (y.y > z.z) {
        const double s = 2 * std::sqrt(1 + y.y - x.x - z.z);
        q = {(z.x - x.z) / s, (y.x + x.y) / s, s / 4, (z.y + y.z) / s};
    } else {
        const double s = 2 * std::sqrt(1 + z.z - x.x - y.y);
        q = {(x.y - y.x) / s, (z.x + x.z) / s, (z.y + y.z) / s, s / 4};
    }
    return normalize(q);
}

}  // namespace isotrace
