#include "geometry/implicit/murakami_quartic.h"

#include <cmath>

namespace isotrace {

std::span<const FieldPiece> MurakamiQuartic::unit_pieces() const {
    static constexpr FieldPiece pieces[] = {{0, 1, true, 2, {1, -2, 1, 0}}};
    return pieces;
}

double MurakamiQuartic::unit_iso_level(double level) const { return 1 - std::sqrt(level); }

}  // namespace isotrace
