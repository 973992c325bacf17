#include "renderer/params/emitted_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace isotrace {
namespace {

std::string shortest(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

}  // namespace

Rgb emitted_colour(const SceneNode& node, const std::string& colour_key, std::optional<Rgb> fallback,
                   const std::string& scale_key) {
    constexpr double kLimit = double(float(kMaxEmitted));  // 1e30 as a colour holds it
    const Rgb colour = fallback && !node.has(colour_key) ? *fallback : node.colour(colour_key);
    const double largest = std::max({double(colour.r), double(colour.g), double(colour.b)});
    if (colour.r < 0 || colour.g < 0 || colour.b < 0) node.fail_at(colour_key, "must not be negative");
    if (!(largest <= kLimit))
        node.fail_at(colour_key, (std::isfinite(largest) ? "the value " + shortest(largest) : std::string("a value")) +
                                     " exceeds the supported maximum of 1e30");
    if (scale_key.empty()) return colour;
    const double scale = node.number_or(scale_key, 1.0, NumberRange::non_negative());
    if (!(largest * scale <= kLimit))
        node.fail_at(scale_key, "the scaled value " + shortest(largest * scale) +
                                    " exceeds the supported maximum of 1e30");
    return colour * float(scale);
}

float saturated_power(double power) { return float(std::min(power, double(std::numeric_limits<float>::max()))); }

}  // namespace isotrace
