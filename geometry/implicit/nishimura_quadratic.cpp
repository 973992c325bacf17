#include "geometry/implicit/nishimura_quadratic.h"

#include <cmath>

namespace isotrace {

double NishimuraQuadratic::unit_value(double x) const {
    if (x < kUnitBreakpoint) return 1 - 3 * x;
    const double u = 1 - std::sqrt(x);
    return 1.5 * u * u;
}

// d/dx of 3/2·(1 − √x)² is −3/2·(1 − √x)/√x; √x ≥ 1/3 on the outer piece, so no division by zero.
double NishimuraQuadratic::unit_derivative(double x) const {
    if (x < kUnitBreakpoint) return -3;
    const double s = std::sqrt(x);
    return -1.5 * (1 - s) / s;
}

std::span<const FieldPiece> NishimuraQuadratic::unit_pieces() const {
    static constexpr FieldPiece pieces[] = {{0, kUnitBreakpoint, true, 1, {1, -3, 0, 0}},
                                            {kUnitBreakpoint, 1, false, 0, {}}};
    return pieces;
}

// The inner piece covers the levels [2/3, 1].
double NishimuraQuadratic::unit_iso_level(double level) const {
    if (level >= 2.0 / 3) return (1 - level) / 3;
    const double s = 1 - std::sqrt(level / 1.5);
    return s * s;
}

}  // namespace isotrace
