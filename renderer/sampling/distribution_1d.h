#pragma once
// Piecewise-constant distribution over [0,1) (or over bin indices) proportional to non-negative weights,
// e.g. one row of an environment map or the powers of the lights.
#include <cstddef>
#include <span>
#include <vector>

namespace isotrace {

class Distribution1D {
public:
    struct ContinuousSample {
        float x;      // in [0,1)
        float pdf;    // density at x with respect to dx
        size_t bin;   // bin containing x
    };
    struct DiscreteSample {
        size_t index;
        float probability;
    };

    // Throws std::invalid_argument for an empty list or a negative, infinite or NaN weight. If all weights
    // are zero the distribution is uniform (so callers need no special case), while integral() stays 0.
    explicit Distribution1D(std::span<const float> weights);

    // u in [0,1). Bins of zero weight are never returned.
    ContinuousSample sample_continuous(float u) const;
    DiscreteSample sample_discrete(float u) const;

    float pdf(float x) const;                   // density at x in [0,1)
    float probability(size_t index) const;      // probability of sample_discrete returning index
    float integral() const { return integral_; }  // integral of the weights as a step function over [0,1)
    size_t size() const { return weights_.size(); }

private:
    size_t find_bin(float u) const;
    float bin_density(size_t bin) const;

    std::vector<float> weights_;  // as sampled: all ones when every input weight was zero
    std::vector<double> cdf_;     // size() + 1 entries, cdf_[0] = 0, cdf_.back() = 1
    std::vector<size_t> guide_;   // size() entries: where find_bin starts for u in [k, k+1) / size()
    double weight_sum_ = 0;       // sum of weights_
    float integral_ = 0;
};

}  // namespace isotrace
