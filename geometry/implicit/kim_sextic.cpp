#include "geometry/implicit/kim_sextic.h"

#include <cmath>

namespace isotrace {

std::span<const FieldPiece> KimSextic::unit_pieces() const {
    static constexpr FieldPiece pieces[] = {{0, 1, true, 3, {1, -3, 3, -1}}};
    return pieces;
}

double KimSextic::unit_iso_level(double level) const { return 1 - std::cbrt(level); }

}  // namespace isotrace
