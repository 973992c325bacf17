#include "renderer/plugin/pixel_filter.h"

#include <vector>

#include "renderer/sampling/distribution_1d.h"

namespace isotrace {
namespace {
// Bins over [-radius, radius]. Samples are drawn exactly from this step-function tabulation of the profile,
// so every sample carries the same weight; at 1024 steps the tabulated filter differs from the analytic one
// only on scales of a thousandth of a pixel.
constexpr int kTableSize = 1024;
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

float PixelFilter::sample_axis(float u) const { return radius_ * (2.0f * table_->sample_continuous(u).x - 1.0f); }

FilterSample PixelFilter::sample(std::array<float, 2> u) const { return {sample_axis(u[0]), sample_axis(u[1]), 1.0f}; }

}  // namespace isotrace
