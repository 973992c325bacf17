#include "renderer/plugin/pixel_filter.h"

#include <vector>

#include "renderer/sampling/distribution_1d.h"

namespace isotrace {
namespace {
constexpr int kTableSize = 1024;  // bins over [-radius, radius]; weights f/pdf stay within ~0.1% of constant
}

PixelFilter::PixelFilter(float radius) : radius_(radius) {}

PixelFilter::~PixelFilter() = default;

void PixelFilter::tabulate() {
    std::vector<float> weights(kTableSize);
    for (int i = 0; i < kTableSize; ++i) {
        const float x = radius_ * (2.0f * (float(i) + 0.5f) / kTableSize - 1.0f);
        weights[std::size_t(i)] = std::max(0.0f, evaluate(x));
    }
    table_ = std::make_unique<Distribution1D>(weights);
}

float PixelFilter::sample_axis(float u, float& weight) const {
    const Distribution1D::ContinuousSample s = table_->sample_continuous(u);
    const float x = radius_ * (2.0f * s.x - 1.0f);
    const float pdf = s.pdf / (2.0f * radius_);  // density per unit x
    weight *= pdf > 0 ? evaluate(x) / pdf : 0.0f;
    return x;
}

FilterSample PixelFilter::sample(std::array<float, 2> u) const {
    FilterSample result;
    result.weight = 1;
    result.dx = sample_axis(u[0], result.weight);
    result.dy = sample_axis(u[1], result.weight);
    return result;
}

}  // namespace isotrace
