#pragma once
// A kernel that is one polynomial piece of degree ≤ 3 in x = r²/R² (Kim's, Wyvill's, Murakami's: FieldPiece with
// is_polynomial), evaluated four lanes at a time: the metaball march's values and bounds (metaball_march.h) and the
// surface regions' bounds (surface_region.h).
#include <array>

#include "renderer/math/double4.h"
#include "renderer/math/fused_bounds.h"

namespace isotrace {

// f(x) = Σ bₖ·xᵏ per lane, zero from x = 1 on (outside the support; also for a lane whose x is NaN), by Horner's rule
// with `mul_add`: RoundedMulAdd for values, BoundMulAdd (fused where the build has FMA, fused_bounds.h) for bounds.
template <class MulAdd = RoundedMulAdd>
Double4 unit_piece_value(const std::array<double, 4>& b, Double4 x, MulAdd mul_add = {}) {
    const Double4 clamped = min4(x, Double4{} + 1.0);
    const Double4 value = mul_add(mul_add(mul_add(clamped, b[3], Double4{} + b[2]), clamped, b[1]), clamped, b[0]);
    return select(x < 1.0, value, Double4{});
}

}  // namespace isotrace
