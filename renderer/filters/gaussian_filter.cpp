// Gaussian filter, shifted down so it reaches zero at the radius (no discontinuity at the support's edge).
#include <cmath>

#include "renderer/plugin/pixel_filter.h"

namespace isotrace {
namespace {

class GaussianFilter final : public PixelFilter {
public:
    GaussianFilter(float radius, float sigma)
        : PixelFilter(radius), sigma_(sigma), edge_(gaussian(radius)) {
        tabulate();
    }
    float evaluate(float x) const override {
        return std::abs(x) >= radius() ? 0.0f : std::max(0.0f, gaussian(x) - edge_);
    }

private:
    float gaussian(float x) const { return std::exp(-x * x / (2 * sigma_ * sigma_)); }
    float sigma_;
    float edge_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(pixel_filter_registry, "gaussian",
                         "Gaussian; radius (pixels, default 1.5), sigma (default 0.5)",
                         [](const SceneNode& node) -> std::unique_ptr<PixelFilter> {
                             const double radius = node.number_or("radius", 1.5, NumberRange::between(0.1, 16));
                             const double sigma = node.number_or("sigma", 0.5, NumberRange::between(0.01, 16));
                             return std::make_unique<GaussianFilter>(float(radius), float(sigma));
                         })

}  // namespace isotrace
