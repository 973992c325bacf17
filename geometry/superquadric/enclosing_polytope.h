#pragma once
// Planes that hold an undeformed superellipsoid where its quadric bounds are loose: star-like and pinched shapes
// (an exponent above 1), which fill little of the ellipsoid through their box's face centres. In u, v, w = |x|/a1,
// |y|/a2, |z|/a3 the gauge is G = ‖(h, w)‖_p1 with h = ‖(u, v)‖_p2, and for any p the sum of a 2-vector's
// components is at most s(p) = max(1, 2^(1 − 1/p)) times its p-norm (Hölder above p = 1, the p-norm's own bound
// below) while its larger component is at most the norm. So G ≤ 1 gives u + w ≤ s1, v + w ≤ s1,
// (u + v)/s2 + w ≤ s1 and u + v ≤ s2: with the signs of x, y and z, up to twenty planes of a convex polytope (the
// first two kinds follow from the third where s2 = 1, the last where s1 = 1). A ray segment that misses it holds no
// crossing, settled by a few products per plane, four planes at a time, instead of the search.
#include <array>
#include <cstddef>

#include "renderer/math/vec3.h"

namespace isotrace {

class EnclosingPolytope {
public:
    EnclosingPolytope() = default;  // none: misses() is always false
    // For radii (a1, a2, a3) and the norms' exponents p1 = 2/ε1 (outer) and p2 = 2/ε2 (inner, horizontal). Holds
    // planes only where an exponent is above 1 (p below 2), where the quadrics leave most of the box to the search.
    EnclosingPolytope(const Vec3d& radii, double p1, double p2);

    bool empty() const { return count_ == 0; }
    // Whether the segment start + τ·direction, τ ∈ [0, length], lies wholly outside the polytope (enlarged by far
    // more than the rounding of its planes, so that no point of the solid is cut off).
    bool misses(const Vec3d& start, const Vec3d& direction, double length) const;

    // The sum bound s(p) of a 2-vector's components by its p-norm.
    static double sum_bound(double p);

private:
    static constexpr std::size_t kMostGroups = 5;
    // Four planes n·x ≤ bound side by side, lane by lane; lanes without a plane hold 0·x ≤ 1.
    struct PlaneGroup {
        double x[4] = {0, 0, 0, 0}, y[4] = {0, 0, 0, 0}, z[4] = {0, 0, 0, 0}, bound[4] = {1, 1, 1, 1};
    };
    std::array<PlaneGroup, kMostGroups> groups_{};
    std::size_t count_ = 0;  // planes
};

}  // namespace isotrace
