#include "renderer/textures/patterns/checker.h"

#include <cmath>
#include <cstdint>

#include "renderer/textures/patterns/box_filter.h"
#include "renderer/textures/patterns/lattice.h"
#include "renderer/textures/patterns/pattern_math.h"

namespace isotrace {
namespace {

// The checker is ½ − ½ s(x) s(y) s(z) with the square wave s(x) = (−1)^⌊x⌋; the box filter of the product is the
// product of the filtered waves.
double square_wave(double x) {
    return (static_cast<std::int64_t>(std::floor(x)) & 1) == 0 ? 1.0 : -1.0;  // x is within ±2^29
}

// The antiderivative of the square wave from 0: a triangle wave between 0 and 1 of period 2.
double triangle_wave(double x) {
    return 1 - std::abs(x - 2 * std::floor(x / 2) - 1);
}

double filtered_square_wave(float x, float footprint) {
    return box_filtered(square_wave, triangle_wave, 0.0, lattice_clamp(x), footprint_or_zero(footprint));
}

}  // namespace

float checker(const Vec3f& p, float footprint) {
    const double product = filtered_square_wave(p.x, footprint) * filtered_square_wave(p.y, footprint) *
                           filtered_square_wave(p.z, footprint);
    return static_cast<float>(0.5 - 0.5 * product);
}

float checker_2d(std::array<float, 2> uv, float footprint) {
    const double product = filtered_square_wave(uv[0], footprint) * filtered_square_wave(uv[1], footprint);
    return static_cast<float>(0.5 - 0.5 * product);
}

}  // namespace isotrace
