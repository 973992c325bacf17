#include "renderer/sampling/area_distribution.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace isotrace {

AreaDistribution::AreaDistribution(std::span<const double> areas) {
    if (areas.empty()) return;
    std::vector<float> weights;
    weights.reserve(areas.size());
    for (const double area : areas) {
        const float weight = float(area);  // finite doubles beyond float's range become infinite here
        weights.push_back(std::isfinite(weight) ? weight : 0.0f);
        total_ += weights.back();
    }
    distribution_.emplace(weights);
}

AreaDistribution::Pick AreaDistribution::pick(float u) const {
    const Distribution1D::ContinuousSample sample = distribution_->sample_continuous(u);
    const double within = double(sample.x) * double(distribution_->size()) - double(sample.bin);
    return {sample.bin, std::clamp(float(within), 0.0f, 0x1.fffffep-1f)};
}

}  // namespace isotrace
