#include "geometry/implicit/wyvill_sextic.h"

#include <algorithm>
#include <cmath>

namespace isotrace {

std::span<const FieldPiece> WyvillSextic::unit_pieces() const {
    static constexpr FieldPiece pieces[] = {{0, 1, true, 3, {1, -22.0 / 9, 17.0 / 9, -4.0 / 9}}};
    return pieces;
}

// With u = 1 − x the level equation is 4u³ + 5u² − 9·level = 0, whose only positive root is the one wanted.
// Closed form: substitute u = v − 5/12 to get v³ + p·v + q = 0, then the trigonometric solution while there are
// three real roots (level < 125/972, the local maximum of f beyond R) and Cardano's otherwise.
double WyvillSextic::unit_iso_level(double level) const {
    constexpr double p = -25.0 / 48;
    const double q = 125.0 / 864 - 9 * level / 4;
    const double discriminant = q * q / 4 + p * p * p / 27;
    double v;
    if (discriminant < 0) {
        const double angle = std::acos(std::clamp(1.5 * q / p * std::sqrt(-3 / p), -1.0, 1.0));
        v = 2 * std::sqrt(-p / 3) * std::cos(angle / 3);  // the largest of the three roots
    } else {
        const double a = std::cbrt(-q / 2 + std::sqrt(discriminant));  // q < 0 here: no cancellation
        v = a - p / (3 * a);
    }
    // The root is at least sqrt(level) (4u³ + 5u² ≤ 9u² for u ≤ 1), which also keeps the Newton step defined.
    double u = std::max(v - 5.0 / 12, std::sqrt(level));
    // One Newton step restores the relative accuracy that v − 5/12 loses when the level is tiny (u → 0).
    u -= (u * u * (4 * u + 5) - 9 * level) / (u * (12 * u + 10));
    return 1 - u;
}

}  // namespace isotrace
