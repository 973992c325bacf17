#pragma once
// Scalar helpers the patterns share: Hermite smoothstep, a clamp to [0, 1] that maps NaN to 0, and the footprint
// every band-limited pattern reads (NaN or negative taken as a point sample).
#include <algorithm>

namespace isotrace {

// x clamped to [0, 1]; NaN gives 0 (every comparison with NaN is false).
constexpr float unit_clamp(float x) {
    return x > 0 ? std::min(x, 1.0f) : 0.0f;
}

// 0 below edge0, 1 above edge1, 3t² − 2t³ in between.
constexpr float smoothstep(float edge0, float edge1, float x) {
    const float t = unit_clamp((x - edge0) / (edge1 - edge0));
    return t * t * (3 - 2 * t);
}

constexpr float footprint_or_zero(float footprint) {
    return footprint > 0 ? footprint : 0.0f;
}

}  // namespace isotrace
