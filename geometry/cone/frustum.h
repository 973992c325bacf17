#pragma once
// A frustum of a right circular cone: the solid between two parallel disks on one axis, a cylinder when their
// radii are equal and a cone when one of them is 0. The surface crossings of a line are solved in double in the
// frustum's own frame (axis along z), after moving the line's origin to its point nearest the frustum's middle, so
// that a ray from far away keeps the precision of one from nearby; each side root gets Newton steps on the side's
// equation itself. The cylinder and cone shapes are both this one.
#include <array>
#include <cstdint>

#include "geometry/cone/axial_frame.h"

namespace isotrace {

enum class FrustumPart : std::uint8_t { Side, Base, Top };

struct FrustumCrossing {
    double t;
    FrustumPart part;
};

// Up to two crossings, ascending in t.
struct FrustumCrossings {
    int count = 0;
    std::array<FrustumCrossing, 2> crossing{};
};

// The frame's origin is the centre of the base disk, its axis points towards the top.
struct Frustum : AxialFrame {
    double height = 1;         // > 0
    double base_radius = 1;    // ≥ 0, not both 0
    double top_radius = 1;
    bool caps = true;          // closed by the two disks (a solid) or the side alone (open)

    // dR/dz: how the radius changes along the axis.
    double slope() const { return (top_radius - base_radius) / height; }
    double radius_at(double z) const { return base_radius + (top_radius - base_radius) * (z / height); }
};

// Closed frustum: where the line origin + t·direction enters and leaves the solid (nothing when it only touches
// it: a grazing contact is a miss). Open frustum: where it crosses the side between the two rims (a line that
// touches the side without crossing it misses).
FrustumCrossings frustum_crossings(const Frustum& frustum, const Vec3d& origin, const Vec3d& direction);

// The outward unit normal of `part` at p (on the axis of a side that closes to an apex: the axis direction).
Vec3d frustum_normal(const Frustum& frustum, FrustumPart part, const Vec3d& p);

// The axis-aligned box of the frustum: the boxes of its two rims.
void frustum_bounds(const Frustum& frustum, Vec3d& lower, Vec3d& upper);

}  // namespace isotrace
