#pragma once
// Where a quadratic a·s² + b·s + c is negative, from its roots (quadratic_roots): the stretches between them when it
// opens upwards, beyond them when it opens downwards, a half-line when it is linear.
#include <array>
#include <limits>

#include "geometry/polynomial/quadratic_roots.h"

namespace isotrace {

struct NegativePiece {
    double lo, hi;  // may be infinite
};

// The pieces of the line where a·s² + b·s + c < 0, up to two, in increasing s; `roots` are its roots (possibly
// polished by the caller). A double root is a touching point, not a piece.
inline int negative_pieces(double a, double b, double c, const QuadraticRoots& roots,
                           std::array<NegativePiece, 2>& pieces) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (a == 0) {
        if (b == 0) {
            if (!(c < 0)) return 0;
            pieces[0] = {-inf, inf};
            return 1;
        }
        pieces[0] = b > 0 ? NegativePiece{-inf, roots.roots[0]} : NegativePiece{roots.roots[0], inf};
        return 1;
    }
    if (roots.count < 2) {  // no root or a double one: the sign of a throughout, but for a touching point
        if (a > 0) return 0;
        pieces[0] = {-inf, inf};
        return 1;
    }
    if (a > 0) {
        pieces[0] = {roots.roots[0], roots.roots[1]};
        return 1;
    }
    pieces[0] = {-inf, roots.roots[0]};
    pieces[1] = {roots.roots[1], inf};
    return 2;
}

}  // namespace isotrace
