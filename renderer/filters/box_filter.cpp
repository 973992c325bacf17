// Box filter: every sample in the pixel's square (radius 0.5 = one pixel) counts equally.
#include "renderer/plugin/pixel_filter.h"

namespace isotrace {
namespace {

class BoxFilter final : public PixelFilter {
public:
    explicit BoxFilter(float radius) : PixelFilter(radius) {}
    float evaluate(float x) const override { return std::abs(x) <= radius() ? 1.0f : 0.0f; }
    FilterSample sample(std::array<float, 2> u) const override {
        return {radius() * (2 * u[0] - 1), radius() * (2 * u[1] - 1), 1.0f};
    }
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(pixel_filter_registry, "box", "box filter; radius (pixels, default 0.5)",
                         [](const SceneNode& node) -> std::unique_ptr<PixelFilter> {
                             return std::make_unique<BoxFilter>(
                                 float(node.number_or("radius", 0.5, NumberRange::between(0.001, 16))));
                         })

}  // namespace isotrace
