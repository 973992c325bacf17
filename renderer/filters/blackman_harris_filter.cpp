// Four-term Blackman-Harris window: compact, smooth and nearly free of ringing.
#include <cmath>
#include <numbers>

#include "renderer/plugin/pixel_filter.h"

namespace isotrace {
namespace {

class BlackmanHarrisFilter final : public PixelFilter {
public:
    explicit BlackmanHarrisFilter(float radius) : PixelFilter(radius) { tabulate(); }
    float evaluate(float x) const override {
        if (std::abs(x) >= radius()) return 0.0f;
        const double phase = 2 * std::numbers::pi * (double(x) / (2 * radius()) + 0.5);  // window over [-r, r]
        return float(0.35875 - 0.48829 * std::cos(phase) + 0.14128 * std::cos(2 * phase) -
                     0.01168 * std::cos(3 * phase));
    }
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(pixel_filter_registry, "blackman_harris", "Blackman-Harris window; radius (default 2)",
                         [](const SceneNode& node) -> std::unique_ptr<PixelFilter> {
                             return std::make_unique<BlackmanHarrisFilter>(
                                 float(node.number_or("radius", 2.0, NumberRange::between(0.1, 16))));
                         })

}  // namespace isotrace
