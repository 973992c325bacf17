#include "tests/support/sturm_sequence.h"

#include <cmath>
#include <limits>

#include "geometry/polynomial/bracketed_root.h"

namespace isotrace {
namespace {

// Remainder coefficients this far below the terms that cancelled in them are taken as zero. Rounding noise is a
// few ulps per division and accumulates along the sequence; a pair of genuine roots 1e-6 apart still leaves
// remainders ~1e-12 of the terms, far above this.
constexpr double kRemainderNoise = 1024 * std::numeric_limits<double>::epsilon();

// 2^-200 of the interval is far below any useful tolerance; a bracket that deep is reported at its midpoint.
constexpr int kMaxBisectionDepth = 200;

// See is_multiple_root: ~1e7 rounding bounds is ~1e-8 of the slope's terms, between the two cases.
constexpr double kMultipleRootSlope = 1e7;

int sign_of(double value) { return (value > 0) - (value < 0); }

// Whether a root found on the square-free part is multiple in p. There p' vanishes too; refined on the
// square-free part the root is accurate to ~1e-14, so p' is that small relative to its terms, while at a simple
// root it is at least the distance to the neighbouring roots (≥ ~1e-8 for roots Sturm can separate).
bool is_multiple_root(const SturmSequence& sequence, const Polynomial& p, double root) {
    if (sequence.repeated_factors().degree() == 0) return false;
    const Polynomial slope = p.derivative();
    return std::abs(slope.evaluate(root)) <= kMultipleRootSlope * slope.evaluation_error_bound(root);
}

}  // namespace

SturmSequence::SturmSequence(const Polynomial& p) {
    members_[size_++] = p.normalised();
    if (p.degree() == 0) return;
    members_[size_++] = p.derivative().normalised();
    while (members_[size_ - 1].degree() > 0) {
        const Polynomial rest = members_[size_ - 2].remainder(members_[size_ - 1], kRemainderNoise);
        if (rest.is_zero()) break;
        members_[size_++] = (-1.0 * rest).normalised();
    }
    if (members_[size_ - 1].degree() == 0) return;
    repeated_factors_ = members_[size_ - 1];
    for (int i = 0; i < size_; ++i) members_[i] = members_[i].quotient(repeated_factors_).normalised();
}

int SturmSequence::sign_changes_at(double t) const {
    int changes = 0, previous_sign = 0;
    for (int i = 0; i < size_; ++i) {
        const int sign = sign_of(members_[i].evaluate(t));
        if (sign == 0) continue;
        if (previous_sign != 0 && sign != previous_sign) ++changes;
        previous_sign = sign;
    }
    return changes;
}

PolynomialRoots sturm_roots(const Polynomial& input, double a, double b, const RootTolerance& tolerance) {
    PolynomialRoots roots;
    const Polynomial p = input.without_negligible_leading_terms(a, b);
    if (p.degree() == 0) return roots;
    const SturmSequence sequence(p);
    const Polynomial& square_free = sequence.square_free_part();
    if (p.is_zero_within_rounding(a)) roots.add({a}, tolerance);

    struct Bracket {
        double lo, hi;
        int changes_at_lo, changes_at_hi, depth;
    };
    // Depth-first, left half first, so roots come out in ascending order; at most one pending bracket per depth.
    std::array<Bracket, kMaxBisectionDepth + 1> pending;
    int pending_count = 0;
    pending[pending_count++] = {a, b, sequence.sign_changes_at(a), sequence.sign_changes_at(b), 0};
    while (pending_count > 0) {
        const Bracket bracket = pending[--pending_count];
        const int root_count = bracket.changes_at_lo - bracket.changes_at_hi;
        if (root_count <= 0) continue;
        const double mid = 0.5 * (bracket.lo + bracket.hi);
        if (root_count == 1) {
            // The square-free part changes sign at every root, multiple ones included.
            const double value_at_lo = square_free.evaluate(bracket.lo), value_at_hi = square_free.evaluate(bracket.hi);
            if (value_at_hi == 0) {
                roots.add({bracket.hi, is_multiple_root(sequence, p, bracket.hi)}, tolerance);
                continue;
            }
            if (sign_of(value_at_lo) * sign_of(value_at_hi) < 0) {
                const double root =
                    refine_bracketed_root(square_free, bracket.lo, bracket.hi, value_at_lo, value_at_hi, tolerance);
                roots.add({root, is_multiple_root(sequence, p, root)}, tolerance);
                continue;
            }
        }
        if (bracket.hi - bracket.lo <= tolerance.width_at(mid) || bracket.depth == kMaxBisectionDepth) {
            // A cluster the tolerance cannot separate (or, with a root exactly at lo, its neighbour): one root.
            roots.add({mid}, tolerance);
            continue;
        }
        const int changes_at_mid = sequence.sign_changes_at(mid);
        pending[pending_count++] = {mid, bracket.hi, changes_at_mid, bracket.changes_at_hi, bracket.depth + 1};
        pending[pending_count++] = {bracket.lo, mid, bracket.changes_at_lo, changes_at_mid, bracket.depth + 1};
    }
    if (p.is_zero_within_rounding(b)) roots.add({b}, tolerance);
    return roots;
}

}  // namespace isotrace
