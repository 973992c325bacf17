#include "renderer/sampling/distribution_1d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace isotrace {
namespace {

constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;  // largest float below 1

}  // namespace

Distribution1D::Distribution1D(std::span<const float> weights) : weights_(weights.begin(), weights.end()) {
    if (weights_.empty()) throw std::invalid_argument("Distribution1D: no weights");
    double sum = 0;
    for (size_t i = 0; i < weights_.size(); ++i) {
        if (!std::isfinite(weights_[i]) || weights_[i] < 0.0f) {
            throw std::invalid_argument("Distribution1D: weight " + std::to_string(i) +
                                        " is negative, infinite or NaN");
        }
        sum += weights_[i];
    }
    integral_ = static_cast<float>(sum / static_cast<double>(weights_.size()));
    if (sum == 0) {
        std::fill(weights_.begin(), weights_.end(), 1.0f);
        sum = static_cast<double>(weights_.size());
    }
    weight_sum_ = sum;

    // Accumulate in double so long tables of tiny weights keep a strictly increasing CDF where weights > 0.
    cdf_.resize(weights_.size() + 1);
    cdf_[0] = 0;
    double running = 0;
    for (size_t i = 0; i < weights_.size(); ++i) {
        running += weights_[i];
        cdf_[i + 1] = running / sum;
    }
    cdf_.back() = 1;

    // guide_[k] = last bin whose CDF start is <= k / size(): a search starting there moves only a step or two.
    guide_.resize(weights_.size());
    size_t bin = 0;
    for (size_t k = 0; k < guide_.size(); ++k) {
        const double start = static_cast<double>(k) / static_cast<double>(guide_.size());
        while (bin + 1 < weights_.size() && cdf_[bin + 1] <= start) ++bin;
        guide_[k] = bin;
    }
}

size_t Distribution1D::find_bin(float u) const {
    // Last i with cdf_[i] <= u. Since u < 1 = cdf_.back(), cdf_[i + 1] > u, so the bin has positive weight.
    const double target = static_cast<double>(u);
    const size_t slot = static_cast<size_t>(std::clamp(target, 0.0, 1.0) * static_cast<double>(guide_.size()));
    size_t bin = guide_[std::min(slot, guide_.size() - 1)];
    while (bin > 0 && cdf_[bin] > target) --bin;  // only when rounding put the slot past u
    while (bin + 1 < weights_.size() && cdf_[bin + 1] <= target) ++bin;
    return bin;
}

Distribution1D::ContinuousSample Distribution1D::sample_continuous(float u) const {
    const size_t bin = find_bin(u);
    const double offset = (u - cdf_[bin]) / (cdf_[bin + 1] - cdf_[bin]);
    const double x = (static_cast<double>(bin) + offset) / static_cast<double>(weights_.size());
    return {std::min(static_cast<float>(x), kOneMinusEpsilon), bin_density(bin), bin};
}

Distribution1D::DiscreteSample Distribution1D::sample_discrete(float u) const {
    if (weights_.size() == 1) return {0, 1.0f};  // what the search and the division give (w / w), without them
    const size_t index = find_bin(u);
    return {index, probability(index)};
}

float Distribution1D::pdf(float x) const {
    const auto bin = static_cast<size_t>(std::max(0.0f, x) * static_cast<float>(weights_.size()));
    return bin_density(std::min(bin, weights_.size() - 1));
}

float Distribution1D::bin_density(size_t bin) const {
    return static_cast<float>(weights_[bin] * static_cast<double>(weights_.size()) / weight_sum_);
}

float Distribution1D::probability(size_t index) const {
    return static_cast<float>(weights_[index] / weight_sum_);
}

}  // namespace isotrace
