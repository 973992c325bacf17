#pragma once
// The annular sector about a bend's centre that holds the bent object. A bend turns each cross-section of the object
// rigidly about the centre (Bend), so a point at bend-frame coordinate s before it lies at distance R − s from the
// centre's axis after it (R = 1/k), at the angle of its height: the object lies between the two cylinders about that
// axis through the extremes of R − s, and within the wedge of its heights' angles. A ray that misses the sector misses
// the object, and the object's crossings lie on the part of the ray between its first entry and last exit.
#include <optional>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct BendSector {
    // The bend direction u, the curvature k and the centre's height z0: a point's coordinates about the centre,
    // scaled by k, are (k·(p·u) − 1, k·(p.z − z0)), so that nothing of size 1/k is formed.
    Vec3d toward;
    double curvature, centre;
    // The sector's radii, scaled by k: 1 − k·s over the object's range of s.
    double inner, outer;
    // sin and cos of the angles of the object's lowest and highest cross-sections.
    double sin_lo, cos_lo, sin_hi, cos_hi;

    // The part [lo, hi] of the segment start + τ·direction, τ ∈ [0, length], from where it first enters the sector
    // (widened by a margin far above the roundings of a superquadric's field) to where it last leaves it; nothing
    // where it misses the sector. For segments within a box a few units across.
    std::optional<Interval> stretch(const Vec3d& start, const Vec3d& direction, double length) const;
};

}  // namespace isotrace
