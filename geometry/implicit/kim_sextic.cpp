#include "geometry/implicit/kim_sextic.h"

#include <cmath>

namespace isotrace {

double KimSextic::unit_value(double x) const {
    const double u = 1 - x;
    return u * u * u;
}

double KimSextic::unit_derivative(double x) const {
    const double u = 1 - x;
    return -3 * u * u;
}

std::span<const FieldPiece> KimSextic::unit_pieces() const {
    static constexpr FieldPiece pieces[] = {{0, 1, true, 3, {1, -3, 3, -1}}};
    return pieces;
}

double KimSextic::unit_iso_level(double level) const { return 1 - std::cbrt(level); }

}  // namespace isotrace
