#include "renderer/render/range_image.h"

#include <algorithm>
#include <cmath>

namespace isotrace {

std::optional<DepthRange> depth_range_of_hits(const DepthMap& map) {
    std::optional<DepthRange> range;
    for (float d : map.depth) {
        if (!std::isfinite(d)) continue;
        if (!range) range = DepthRange{d, d};
        range->near = std::min(range->near, d);
        range->far = std::max(range->far, d);
    }
    return range;
}

std::uint8_t range_grey_level(float depth, const DepthRange& range) {
    const std::uint8_t near_level = range.near_is_bright ? 255 : 0, far_level = 255 - near_level;
    if (!std::isfinite(depth)) return far_level;
    if (!(range.far > range.near)) return near_level;
    const double numerator = range.near_is_bright ? double(range.far) - double(depth) : double(depth) - double(range.near);
    const double g = numerator * 256.0 / (double(range.far) - double(range.near));
    return std::uint8_t(std::clamp(std::floor(g), 0.0, 255.0));
}

std::vector<std::uint8_t> range_image(const DepthMap& map, const DepthRange& range) {
    std::vector<std::uint8_t> grey(map.depth.size());
    std::transform(map.depth.begin(), map.depth.end(), grey.begin(),
                   [&](float d) { return range_grey_level(d, range); });
    return grey;
}

}  // namespace isotrace
