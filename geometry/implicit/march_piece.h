#pragma once
// What every blob march shares (the general one, field_march.h, and the one for metaballs of a single polynomial
// kernel piece, metaball_march.h): the stretch marched, the crossings it reports, its statistics, and the work on one
// piece on which F is a polynomial — its Bernstein test and, when that cannot rule a crossing out, its sign
// changes in order. F > 0 is inside; F = 0 exactly counts as outside; a tangent touch (a double root) is no crossing.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "geometry/implicit/blob_query_work.h"
#include "geometry/implicit/field_crossing.h"
#include "geometry/implicit/sphere_prefilter.h"
#include "geometry/polynomial/bernstein.h"
#include "geometry/polynomial/bracketed_root.h"
#include "geometry/polynomial/monotone_root_finder.h"
#include "geometry/polynomial/polynomial.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// The stretch of a ray one march examines.
struct MarchStretch {
    Vec3d origin, direction;  // direction need not be unit length
    double t_begin = 0, t_end = 0;  // the part marched (a cell's part of the ray)
    double t_min = 0, t_max = 0;    // crossings are reported only inside (t_min, t_max)
};

// The float test of the listed elements' bounding spheres against the stretch (sphere_prefilter.h).
inline SegmentNearSpheres near_stretch_test(const MarchStretch& stretch, double centre_bound) {
    const double length_d = length(stretch.direction);
    return SegmentNearSpheres(stretch.origin + stretch.direction * (0.5 * (stretch.t_begin + stretch.t_end)),
                              stretch.direction / length_d, 0.5 * (stretch.t_end - stretch.t_begin) * length_d,
                              centre_bound);
}

// Far above the rounding of a nearest point of the stretch (a few ulps of the coordinates' magnitudes; the centres
// are at most centre_bound from the origin): the margin of the exact test that keeps an element near the stretch.
// An element kept because of it that misses the stretch is dropped by its exact chord.
inline double nearest_approach_rounding(const MarchStretch& stretch, double centre_bound) {
    return 1e-12 * (max_component(abs(stretch.origin)) +
                    length(stretch.direction) * std::max(std::abs(stretch.t_begin), std::abs(stretch.t_end)) +
                    centre_bound);
}

// An upper bound of Σ wᵢ·fᵢ on the whole stretch (from the elements' nearest approaches) below T: no crossing (the
// margin dwarfs the rounding of the nearest approaches).
inline bool stretch_below_threshold(double upper, double threshold) { return upper * (1 + 1e-9) < threshold; }

// Two ray parameters this close are one place: a crossing that two cells find on their shared face, or a hard-cube
// face found in the cube's frame against a stretch start found in world coordinates.
inline double same_place_tolerance(double t) { return 1e-12 * (1 + std::abs(t)); }

namespace march_piece {

inline int sign_of(double value) { return value > 0 ? 1 : -1; }

// F + T at a stretch's start above T beyond any rounding (a ray grazing the surface where the stretch starts is
// not inside there); `weights` is Σ |wᵢ| over the elements counting there (F + T cannot exceed it, f ≤ 1).
inline bool inside_beyond_rounding(double f, double threshold, double weights) {
    return f > 1e-9 * (threshold + weights);
}

// A piece settled by the counting elements' own ranges: an upper bound of Σ wᵢ·fᵢ on it below T beyond rounding
// (no crossing, coming from outside) ...
inline bool below_threshold(double high, double threshold) {
    return high - threshold < -1e-12 * (2 * std::abs(high) + threshold);
}
// ... or bounds on both sides that keep it all below or all above T beyond rounding.
inline bool one_side_of_threshold(double low, double high, double threshold) {
    const double slack = 1e-12 * (std::abs(low) + std::abs(high) + threshold);
    return high - threshold < -slack || low - threshold > slack;
}

// Σ |cᵢ|·xⁱ: bounds |p(s)| for |s| ≤ x, and the effect of coefficient errors.
inline double magnitude_at(const std::array<double, kMaxPolynomialDegree + 1>& c, double x) {
    double m = 0;
    for (int i = kMaxPolynomialDegree; i >= 0; --i) m = m * x + std::abs(c[std::size_t(i)]);
    return m;
}

// The Bernstein test of the piece [s0, s0 + width] of `sum` (F as a polynomial in s, the sum of `terms` terms whose
// coefficients' magnitudes add up to `magnitude`): writes F on the piece in u ∈ [0, 1] to `on_piece` and returns the
// signs of its control polygon (bernstein_signs; 0 variations: no crossing), allowing for the rounding of the terms'
// sum and of the shift to the piece (2·degree + 2 operations per coefficient). `on_piece` is the caller's, declared
// once per march: declared per piece, even as an optional, its 104 bytes were cleared (a rep stos) on every piece.
inline BernsteinSigns bernstein_variations(const Polynomial& sum,
                                           const std::array<double, kMaxPolynomialDegree + 1>& magnitude, int terms,
                                           double s0, double width, Polynomial& on_piece) {
    on_piece = sum.compose_linear(s0, width);
    const double rounding = 4 * std::numeric_limits<double>::epsilon() * (terms + 2 * sum.degree() + 2) *
                            magnitude_at(magnitude, std::abs(s0) + width);
    return bernstein_signs(on_piece, rounding);
}

// The Bernstein test of F on a piece composed directly in u ∈ [0, 1] from `terms` terms (MetaballMarch): every value
// its composition rounds is at most `magnitude` (Σ over the terms, and T), and each coefficient went through at most
// 20 roundings (the quadratic x(u), three Horner steps of three products and two sums, the weight, the sum of terms).
inline BernsteinSigns bernstein_signs_on_piece(const Polynomial& on_piece, int terms, double magnitude) {
    return bernstein_signs(on_piece, 4 * std::numeric_limits<double>::epsilon() * (terms + 20) * magnitude);
}

// Reports the sign changes of F = on_piece(u) on the piece [t0, t0 + width] (u = (t − t0)/width) in increasing t,
// through crossing(t, sign before), which returns true to stop the march; `signs` is the piece's Bernstein test
// (bernstein_variations or bernstein_signs_on_piece; not 0 variations), whose polygon crossing starts the search for a
// lone root. previous_sign is F's sign just before the piece, and F's sign at its end on return. Returns true
// when the march must stop.
template <class Crossing>
bool polynomial_piece_crossings(const Polynomial& on_piece, const BernsteinSigns& signs, double t0, double width,
                                int& previous_sign, BlobQueryWork& work, Crossing&& crossing) {
    ++work.polynomial_solves;
    // A start of exactly zero is a root at t0 the previous piece already ended on: no step. (Any other start is
    // taken at its sign: near zero, a crossing at t0 is where the root lies, within rounding.)
    if (on_piece[0] != 0) {
        const int sign_at_start = sign_of(on_piece[0]);
        if (sign_at_start != previous_sign && crossing(t0, previous_sign)) return true;
        previous_sign = sign_at_start;
    }
    RootFinderWork root_work;
    const double at_start = on_piece[0], at_end = on_piece.evaluate(1);
    const bool bracketed = signs.variations == 1 && sign_of(at_start) != sign_of(at_end);
    if (bracketed) {
        // Exactly one root, a simple one, and the piece brackets it (bernstein.h): no critical points to find first,
        // which would cost more than the refinement itself.
        const double root =
            refine_bracketed_root(on_piece, 0, 1, at_start, at_end, {}, &root_work, signs.polygon_crossing);
        const int after = sign_of(at_end);
        if (after != previous_sign) {
            const int before = previous_sign;
            previous_sign = after;
            if (crossing(t0 + root * width, before)) {
                work.root_iterations += root_work.iterations;
                return true;
            }
        }
    }
    // Roots in order; a tangent root touches without crossing, and a root whose direction repeats the last sign
    // change is the piece-start step found again.
    for (double from = 0; !bracketed && from <= 1;) {
        const auto root = first_root(on_piece, from, 1, {}, &root_work);
        if (!root) break;
        from = root->t + 1e-12;
        if (root->tangent) continue;
        const int after = on_piece.evaluate_with_derivative(root->t).derivative > 0 ? 1 : -1;
        if (after == previous_sign) continue;
        const int before = previous_sign;
        previous_sign = after;
        if (crossing(t0 + root->t * width, before)) {
            work.root_iterations += root_work.iterations;
            return true;
        }
    }
    work.root_iterations += root_work.iterations;
    if (!on_piece.is_zero_within_rounding(1)) previous_sign = sign_of(on_piece.evaluate(1));
    return false;
}

}  // namespace march_piece
}  // namespace isotrace
