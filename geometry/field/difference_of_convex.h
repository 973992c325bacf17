#pragma once
// Bounds of φ = c − s over a stretch [a, b] of a ray, where c and s are convex functions of t known by their values
// and slopes at a and b: a convex function lies above its tangents and below its chords, so
//   max(tangents of c) − chord of s  ≤  φ  ≤  chord of c − max(tangents of s),
// both sides piecewise linear with at most one kink, whose extremes over [a, b] are at an end or at the kink. The
// bounds close in quadratically as the stretch shrinks (interval arithmetic only linearly), and the slopes bound
// φ′ by monotonicity of c′ and s′. Used where an inside function is such a difference and neither convex nor
// concave along the ray (superellipsoids with one exponent below 2 and one above, between coordinate planes).
// A non-finite slope (a cusp, or unknown) gives no tangent there.
#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/math/interval.h"

namespace isotrace {

struct ConvexSample {
    double value, slope;
};

// φ = convex − subtracted at one point.
struct DifferenceOfConvexSample {
    ConvexSample convex, subtracted;
};

namespace difference_of_convex_detail {

// The least value over [a, b] of max(tangents of f at a and b) − (the line through (a, line_a) and (b, line_b)).
inline double least_above_tangents(double a, const ConvexSample& f_a, double b, const ConvexSample& f_b,
                                   double line_a, double line_b) {
    const bool tangent_a = std::isfinite(f_a.slope), tangent_b = std::isfinite(f_b.slope);
    if (!tangent_a && !tangent_b) return -std::numeric_limits<double>::infinity();
    const double width = b - a;
    const auto line = [&](double t) { return line_a + (line_b - line_a) * ((t - a) / width); };
    const auto below = [&](double t) {
        double v = -std::numeric_limits<double>::infinity();
        if (tangent_a) v = std::max(v, f_a.value + f_a.slope * (t - a));
        if (tangent_b) v = std::max(v, f_b.value + f_b.slope * (t - b));
        return v - line(t);
    };
    double least = std::min(below(a), below(b));
    if (tangent_a && tangent_b && f_b.slope > f_a.slope) {
        const double kink = (f_b.value - f_a.value + f_a.slope * a - f_b.slope * b) / (f_a.slope - f_b.slope);
        if (kink > a && kink < b) least = std::min(least, below(kink));
    }
    return least;
}

}  // namespace difference_of_convex_detail

// Contains φ over [a, b] (a < b).
inline Interval difference_of_convex_range(double a, const DifferenceOfConvexSample& at_a, double b,
                                           const DifferenceOfConvexSample& at_b) {
    using difference_of_convex_detail::least_above_tangents;
    const double lo = least_above_tangents(a, at_a.convex, b, at_b.convex, at_a.subtracted.value, at_b.subtracted.value);
    // max(chord of c − tangents of s) = −min(tangents of s − chord of c).
    const double hi = -least_above_tangents(a, at_a.subtracted, b, at_b.subtracted, at_a.convex.value, at_b.convex.value);
    return {lo, hi};
}

// Contains φ′ over [a, b]: c′ rises from c′(a) to c′(b), s′ likewise.
inline Interval difference_of_convex_slope(const DifferenceOfConvexSample& at_a, const DifferenceOfConvexSample& at_b) {
    const double lo = at_a.convex.slope - at_b.subtracted.slope, hi = at_b.convex.slope - at_a.subtracted.slope;
    if (!std::isfinite(lo) || !std::isfinite(hi)) return Interval::unbounded();
    return {lo, hi};
}

}  // namespace isotrace
