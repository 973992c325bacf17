#include "geometry/implicit/blinn_exponential.h"

#include <cmath>

#include "geometry/implicit/parameter_check.h"

namespace isotrace {

BlinnExponential::BlinnExponential(double sharpness) : sharpness_(sharpness), expm1_minus_a_(std::expm1(-sharpness)) {
    require_parameter(std::isfinite(sharpness) && sharpness > 0, "sharpness", "must be finite and > 0", sharpness);
}

// e^(−ax) − e^(−a) = −e^(−ax)·expm1(−a(1 − x)): no cancellation near the cut, no overflow for large a.
std::span<const FieldPiece> BlinnExponential::unit_pieces() const {
    static constexpr FieldPiece pieces[] = {{0, 1, false, 0, {}}};
    return pieces;
}

// e^(−ax) = level + (1 − level)·e^(−a): a sum of two positive terms, so accurate even for tiny levels (the
// equivalent log1p((1 − level)·expm1(−a)) cancels there when a is large).
double BlinnExponential::unit_iso_level(double level) const {
    return -std::log(level + (1 - level) * std::exp(-sharpness_)) / sharpness_;
}

}  // namespace isotrace
