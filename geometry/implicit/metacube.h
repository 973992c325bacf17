#pragma once
// A skeletal element of a blob group: the metacube M = (C, d, R, w) of Kim & Kim 2000, with two extensions
// beyond the paper: the box may be rotated (a local frame) and non-uniform (half-sizes dx, dy, dz).
//
// Its field at P is w·f(dist²), dist = the Euclidean distance from P to the solid box (the skeleton). In the
// box's local coordinates p, dist² = Σₖ max(0, |pₖ| − dₖ)²; this one formula is the paper's face, edge and
// vertex regions (one, two or three axes with |pₖ| > dₖ) and is 0 inside the box. Special cases:
//   - d = 0: a metaball (dist = |P − C|). Use Metacube::metaball.
//   - R = 0: a hard cube, the paper's limit. Its field is w on the closed box and 0 outside (the limit of
//     w·f(dist²/R²) as R → 0), a step with no gradient: the intersector treats it as the exact box skeleton()
//     and takes normals from the box faces. Every half-size must then be > 0 (a flat box would be invisible).
//   - w < 0: carving (negative density), allowed.
#include <array>

#include "geometry/implicit/field_function.h"
#include "renderer/math/quaternion.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// A solid box with orthonormal local axes (world directions; a reflection is harmless, the box is symmetric).
struct OrientedBox {
    Vec3d centre;
    std::array<Vec3d, 3> axes = {Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 1}};
    Vec3d half_size;

    // Coordinates of a world point along the axes, relative to the centre.
    Vec3d to_local(const Vec3d& world_point) const;
    Vec3d to_local_vector(const Vec3d& world_vector) const;
    Vec3d to_world_vector(const Vec3d& local_vector) const;
};

// An axis-aligned world box, lower ≤ upper.
struct WorldBounds {
    Vec3d lower, upper;
};

class Metacube {
public:
    // Throws std::invalid_argument naming the field at fault: "centre" (not finite), "rotation" (axes not finite
    // and orthonormal), "half_size" (not finite and ≥ 0), "radius" (not finite and ≥ 0, or 0 with a half-size 0),
    // "weight" (not finite).
    Metacube(const OrientedBox& skeleton, double radius, double weight);
    static Metacube metaball(const Vec3d& centre, double radius, double weight);

    // The box, its axes rebuilt from the stored orientation: exactly the given ones when they are the world axes,
    // within a few units of rounding (< 4e-15) otherwise; a left-handed frame comes back right-handed (the box is
    // symmetric); a metaball has the world axes.
    OrientedBox skeleton() const;
    const Vec3d& centre() const { return centre_; }
    const Vec3d& half_size() const { return half_size_; }
    bool is_metaball() const { return half_size_ == Vec3d(0, 0, 0); }
    double radius() const { return radius_; }
    double weight() const { return weight_; }
    // The centre's x, y, z, the radius and the weight, side by side: the metaball march loads the first four of
    // several elements as lanes and transposes them.
    const double* centre_radius_weight() const { return &centre_.x; }
    bool is_hard_cube() const { return radius_ == 0; }
    // Half the skeleton box's diagonal, and the radius of the sphere about the centre that holds the support.
    double half_diagonal() const { return length(half_size_); }
    double support_radius() const { return radius_ + half_diagonal(); }

    // Squared distance from a world point to the solid box.
    double distance_squared(const Vec3d& point) const {
        const Vec3d offset = offset_beyond_box(point);
        return dot(offset, offset);
    }
    // w·f(dist²), or for a hard cube w on the closed box and 0 outside. Kernel is FieldFunction or, for direct
    // calls, one of its final classes.
    template <class Kernel>
    double field(const Kernel& kernel, const Vec3d& point) const {
        const double r2 = distance_squared(point);
        if (is_hard_cube()) return r2 == 0 ? weight_ : 0;
        return weight_ * FieldFunction::kernel_value(kernel, r2, radius_);
    }
    // ∇(w·f(dist²)) = w·f'(dist²)·∇dist²; the surface normal of a blob group is −Σ of these. Zero for a hard
    // cube (see above) and wherever dist ≥ R.
    template <class Kernel>
    Vec3d field_gradient(const Kernel& kernel, const Vec3d& point) const {
        if (is_hard_cube()) return {};
        const Vec3d offset = offset_beyond_box(point);
        const double slope = weight_ * FieldFunction::kernel_derivative(kernel, dot(offset, offset), radius_);
        const Vec3d gradient = offset * (2 * slope);
        return is_metaball() ? gradient : orientation_.rotate(gradient);  // a metaball has no frame to turn by
    }
    // The tight world bounds of the support {dist ≤ R} (the per-primitive bounds for Embree).
    WorldBounds support_bounds() const;
    // Bounds of dist² over the closed box: no point of the box is nearer than the first (exact for a metaball),
    // none farther than the second (exact). The kernel is monotone in dist², so they bound the field there.
    double nearest_squared_distance(const WorldBounds& box) const {
        if (is_metaball()) {  // inline: the surface-region search's most frequent call
            const Vec3d gap = max(max(box.lower - centre_, centre_ - box.upper), Vec3d(0, 0, 0));
            return dot(gap, gap);
        }
        return nearest_squared_distance_from_ball(box);
    }
    double farthest_squared_distance(const WorldBounds& box) const {
        if (is_metaball()) {  // the corner farthest from the centre on each axis
            const Vec3d reach = max(abs(box.lower - centre_), abs(box.upper - centre_));
            return dot(reach, reach);
        }
        return farthest_squared_distance_at_corners(box);
    }

private:
    // nearest_squared_distance of a metacube: dist is 1-Lipschitz, so dist ≥ dist(middle of the box) − half its
    // diagonal.
    double nearest_squared_distance_from_ball(const WorldBounds& box) const;
    // farthest_squared_distance of a metacube: dist² is convex in P, so its largest value is at a corner.
    double farthest_squared_distance_at_corners(const WorldBounds& box) const;
    // Per local axis, the signed amount by which p lies beyond the box's slab (0 inside the slab): its squared
    // length is dist² and twice it is ∇dist² in local coordinates. Inline for a metaball (the normal of every blob
    // hit sums these), out of line through the frame otherwise.
    Vec3d offset_beyond_box(const Vec3d& world_point) const {
        return is_metaball() ? world_point - centre_ : offset_beyond_rotated_box(world_point);
    }
    Vec3d offset_beyond_rotated_box(const Vec3d& world_point) const;

    // What the ray march reads first comes first. The frame is a unit quaternion rather than three axes: 96 bytes
    // per element instead of 136 (issue 9's memory budget is 256 bytes per element, cells and Embree included).
    Vec3d centre_;
    double radius_;
    double weight_;
    Vec3d half_size_;
    Quaternion orientation_;
};

}  // namespace isotrace
