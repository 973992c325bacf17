#include "geometry/implicit/metacube.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "geometry/implicit/parameter_check.h"
#include "renderer/math/box_corner.h"

namespace isotrace {
namespace {

// Scene rotations are composed in double, so their axes are orthonormal to ~1e-15; anything worse is a mistake.
constexpr double kOrthonormalityTolerance = 1e-9;

bool is_orthonormal(const std::array<Vec3d, 3>& axes) {
    for (int i = 0; i < 3; ++i) {
        if (!is_finite(axes[i])) return false;
        for (int j = i; j < 3; ++j)
            if (std::abs(dot(axes[i], axes[j]) - (i == j ? 1 : 0)) > kOrthonormalityTolerance) return false;
    }
    return true;
}

}  // namespace

Vec3d OrientedBox::to_local(const Vec3d& world_point) const { return to_local_vector(world_point - centre); }

Vec3d OrientedBox::to_local_vector(const Vec3d& world_vector) const {
    return {dot(axes[0], world_vector), dot(axes[1], world_vector), dot(axes[2], world_vector)};
}

Vec3d OrientedBox::to_world_vector(const Vec3d& local_vector) const {
    return axes[0] * local_vector.x + axes[1] * local_vector.y + axes[2] * local_vector.z;
}

Metacube::Metacube(const OrientedBox& skeleton, double radius, double weight)
    : centre_(skeleton.centre), radius_(radius), weight_(weight), half_size_(skeleton.half_size) {
    static_assert(offsetof(Metacube, radius_) == 3 * sizeof(double) &&
                      offsetof(Metacube, weight_) == 4 * sizeof(double),
                  "centre_radius_weight(): five doubles side by side");
    require_components(skeleton.centre, [](double c) { return std::isfinite(c); }, "centre", "must be finite");
    if (!is_orthonormal(skeleton.axes))
        throw std::invalid_argument("rotation: the local axes must be finite and orthonormal");
    require_components(skeleton.half_size, [](double d) { return std::isfinite(d) && d >= 0; }, "half_size",
                       "every component must be finite and >= 0");
    require_parameter(std::isfinite(radius) && radius >= 0, "radius", "must be finite and >= 0", radius);
    require_parameter(std::isfinite(weight), "weight", "must be finite", weight);
    const Vec3d& d = skeleton.half_size;
    require_parameter(radius > 0 || (d.x > 0 && d.y > 0 && d.z > 0), "radius",
                      "may be 0 (a hard cube) only when every half_size is > 0", radius);
    // A quaternion holds rotations only; the box is symmetric, so a reflected frame is the same box with its last
    // axis turned round. A metaball has no frame.
    const std::array<Vec3d, 3>& a = skeleton.axes;
    const bool right_handed = dot(cross(a[0], a[1]), a[2]) > 0;
    orientation_ =
        is_metaball() ? Quaternion::identity() : Quaternion::from_axes(a[0], a[1], right_handed ? a[2] : -a[2]);
}

OrientedBox Metacube::skeleton() const {
    return {centre_, {orientation_.axis_x(), orientation_.axis_y(), orientation_.axis_z()}, half_size_};
}

Metacube Metacube::metaball(const Vec3d& centre, double radius, double weight) {
    OrientedBox point;
    point.centre = centre;
    return Metacube(point, radius, weight);
}

Vec3d Metacube::offset_beyond_rotated_box(const Vec3d& world_point) const {
    const Vec3d p = orientation_.rotate_back(world_point - centre_);
    Vec3d offset;
    for (int k = 0; k < 3; ++k) offset[k] = std::copysign(std::max(0.0, std::abs(p[k]) - half_size_[k]), p[k]);
    return offset;
}

// The support is the box swept by a ball of radius R: per world axis j the box reaches Σₖ |axes[k]ⱼ|·dₖ from
// the centre, and the ball adds R whatever the rotation.
WorldBounds Metacube::support_bounds() const {
    Vec3d reach{radius_, radius_, radius_};
    if (!is_metaball()) {  // the cell build asks this of every element many times: no frame for a metaball
        const OrientedBox box = skeleton();
        for (int k = 0; k < 3; ++k) reach += abs(box.axes[k]) * half_size_[k];
    }
    return {centre_ - reach, centre_ + reach};
}

double Metacube::nearest_squared_distance_from_ball(const WorldBounds& box) const {
    const double gap = std::sqrt(distance_squared((box.lower + box.upper) * 0.5)) - 0.5 * length(box.upper - box.lower);
    return gap > 0 ? gap * gap : 0;
}

double Metacube::farthest_squared_distance_at_corners(const WorldBounds& box) const {
    double farthest = 0;
    for (int corner = 0; corner < 8; ++corner)
        farthest = std::max(farthest, distance_squared(box_corner(box.lower, box.upper, corner)));
    return farthest;
}

static_assert(sizeof(Metacube) == 96, "the per-element budget (see the members)");

}  // namespace isotrace
