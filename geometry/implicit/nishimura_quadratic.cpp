#include "geometry/implicit/nishimura_quadratic.h"

#include <cmath>

namespace isotrace {

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
