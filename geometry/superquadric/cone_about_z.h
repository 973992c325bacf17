#pragma once
// A solid cone about z, (kx·x)² + (ky·y)² ≤ (α + β·z)² where α + β·z > 0 (a cylinder when β = 0), that holds a
// deformed superquadric: the undeformed solid lies in an elliptic cylinder around z (Superellipsoid), which a twist
// keeps once it is made round and a taper widens into a cone. A ray that misses it misses the solid, and the solid's
// crossings lie on the part of the ray inside it.
#include <optional>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct ConeAboutZ {
    double kx, ky, alpha, beta;

    double radius_scale(double z) const { return alpha + beta * z; }
    // The part [lo, hi] of the segment start + τ·direction, τ ∈ [0, length], inside the cone widened by a margin far
    // above the roundings of a superquadric's field (so that the field is positive where the part ends before
    // `length` or begins after 0); nothing where the segment misses it. The segment must lie where α + β·z > 0, and
    // within a box a few units across.
    std::optional<Interval> stretch(const Vec3d& start, const Vec3d& direction, double length) const;
};

}  // namespace isotrace
