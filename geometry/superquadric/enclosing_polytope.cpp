#include "geometry/superquadric/enclosing_polytope.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/math/double4.h"

namespace isotrace {

double EnclosingPolytope::sum_bound(double p) { return p <= 1 ? 1.0 : std::exp2(1 - 1 / p); }

EnclosingPolytope::EnclosingPolytope(const Vec3d& radii, double p1, double p2) {
    if (p1 >= 2 && p2 >= 2) return;
    // Within the box the planes' values are a few units, rounded to 10⁻¹⁵: the margin is far above that.
    constexpr double kMargin = 1e-8;
    const double s1 = sum_bound(p1), s2 = sum_bound(p2);
    const auto add = [&](double cu, double cv, double cw, double bound) {
        PlaneGroup& group = groups_[count_ / 4];
        const std::size_t lane = count_ % 4;
        group.x[lane] = cu / radii.x, group.y[lane] = cv / radii.y, group.z[lane] = cw / radii.z;
        group.bound[lane] = bound + kMargin;
        ++count_;
    };
    for (const double a : {1.0, -1.0})
        for (const double b : {1.0, -1.0}) {
            add(a / s2, b / s2, 1, s1);  // (u + v)/s2 + w ≤ s1, z ≥ 0
            add(a / s2, b / s2, -1, s1);  // and z ≤ 0
        }
    if (s2 > 1)
        for (const double a : {1.0, -1.0})
            for (const double b : {1.0, -1.0}) {
                add(a, 0, b, s1);  // u + w ≤ s1
                add(0, a, b, s1);  // v + w ≤ s1
            }
    if (s1 > 1)
        for (const double a : {1.0, -1.0})
            for (const double b : {1.0, -1.0}) add(a, b, 0, s2);  // u + v ≤ s2
}

bool EnclosingPolytope::misses(const Vec3d& start, const Vec3d& direction, double length) const {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const Double4 zero{0, 0, 0, 0};
    Double4 lo = zero, hi = Double4{length, length, length, length};
    Mask4 parallel_outside = zero < zero;
    for (std::size_t g = 0; g * 4 < count_; ++g) {
        const PlaneGroup& group = groups_[g];
        const Double4 nx = load4(group.x), ny = load4(group.y), nz = load4(group.z);
        const Double4 at_start = nx * start.x + ny * start.y + nz * start.z;
        const Double4 rate = nx * direction.x + ny * direction.y + nz * direction.z;
        const Double4 room = load4(group.bound) - at_start;
        const Double4 reach = room / rate;  // where the segment crosses the plane; masked where it runs along it
        hi = min4(hi, select(rate > zero, reach, Double4{kInfinity, kInfinity, kInfinity, kInfinity}));
        lo = max4(lo, select(rate < zero, reach, -Double4{kInfinity, kInfinity, kInfinity, kInfinity}));
        parallel_outside |= (rate == zero) & (room < zero);
    }
    const double enter = std::max(std::max(lo[0], lo[1]), std::max(lo[2], lo[3]));
    return mask_bits(parallel_outside) != 0 || enter > lane_min(hi);
}

}  // namespace isotrace
