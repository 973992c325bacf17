#include "renderer/image_compare/error_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isotrace {

std::array<std::uint8_t, 3> magma_like(double t) {
    static constexpr double anchors[9][3] = {
        {0.000, 0.000, 0.016}, {0.110, 0.063, 0.267}, {0.310, 0.071, 0.482}, {0.506, 0.145, 0.506}, {0.710, 0.212, 0.478},
        {0.898, 0.314, 0.392}, {0.984, 0.529, 0.380}, {0.996, 0.761, 0.529}, {0.988, 0.992, 0.749}};
    t = std::isnan(t) ? 1.0 : std::clamp(t, 0.0, 1.0);
    const double position = t * 8;
    const int i = std::min(int(position), 7);
    const double f = position - i;
    std::array<std::uint8_t, 3> colour{};
    for (int c = 0; c < 3; ++c) {
        const double v = anchors[i][c] + f * (anchors[i + 1][c] - anchors[i][c]);
        colour[std::size_t(c)] = std::uint8_t(std::lround(255 * v));
    }
    return colour;
}

std::vector<std::uint8_t> false_colour(const std::vector<float>& values, double full_scale) {
    if (!(full_scale > 0)) throw std::invalid_argument("false_colour: the full scale must be > 0");
    std::vector<std::uint8_t> bytes;
    bytes.reserve(values.size() * 3);
    for (float v : values) {
        const auto colour = magma_like(double(v) / full_scale);
        bytes.insert(bytes.end(), colour.begin(), colour.end());
    }
    return bytes;
}

}  // namespace isotrace
