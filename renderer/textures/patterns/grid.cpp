#include "renderer/textures/patterns/grid.h"

#include <algorithm>
#include <cmath>

#include "renderer/textures/patterns/box_filter.h"
#include "renderer/textures/patterns/lattice.h"
#include "renderer/textures/patterns/pattern_math.h"

namespace isotrace {
namespace {

// The grid is 1 − Π(1 − line(axis)), with line(x) = 1 within width/2 of an integer; the box filter of the
// product is the product of the filtered factors.
double filtered_gap(float x, double width, float footprint) {
    const auto line = [width](double t) { return width > 0 && 2 * std::abs(t - std::round(t)) <= width ? 1.0 : 0.0; };
    // The antiderivative of line from −½: width per whole period, plus the part of the current line passed.
    const auto covered = [width](double t) {
        const double shifted = t + 0.5, period = std::floor(shifted);
        return period * width + std::clamp(shifted - period - (0.5 - width / 2), 0.0, width);
    };
    return 1 - box_filtered(line, covered, width, lattice_clamp(x), footprint_or_zero(footprint));
}

}  // namespace

float grid(const Vec3f& p, float line_width, float footprint) {
    const double width = unit_clamp(line_width);
    const double gaps = filtered_gap(p.x, width, footprint) * filtered_gap(p.y, width, footprint) *
                        filtered_gap(p.z, width, footprint);
    return static_cast<float>(1 - gaps);
}

float grid_2d(std::array<float, 2> uv, float line_width, float footprint) {
    const double width = unit_clamp(line_width);
    return static_cast<float>(1 - filtered_gap(uv[0], width, footprint) * filtered_gap(uv[1], width, footprint));
}

}  // namespace isotrace
