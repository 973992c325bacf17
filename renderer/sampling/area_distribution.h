#pragma once
// Area-proportional choice of one primitive of a shape (one sphere of a sphere list, one triangle of a mesh),
// the first step of sampling a point uniformly over the shape's area: the areas become a Distribution1D, and a
// pick returns the primitive together with where u fell inside that primitive's share of [0, 1), rescaled to
// [0, 1), so that one random number chooses the primitive and still serves for the point on it.
#include <cstddef>
#include <optional>
#include <span>

#include "renderer/sampling/distribution_1d.h"

namespace isotrace {

class AreaDistribution {
public:
    struct Pick {
        std::size_t index;
        float reused_u;  // in [0, 1), uniform and independent of the index when u is
    };

    AreaDistribution() = default;
    // One area per primitive; an area that is not finite as a float counts as 0 (that primitive is never picked;
    // a shape that large lies beyond the world limit and is refused where the scene is read).
    explicit AreaDistribution(std::span<const double> areas);

    // The sum of the areas as sampled (each rounded to float, as the distribution holds them), so that
    // 1 / total() is the density per unit area of the points the picks lead to.
    double total() const { return total_; }
    // Requires total() > 0. The reused number's resolution is that of u divided by the primitive's
    // probability (coarse only for millions of primitives).
    Pick pick(float u) const;

private:
    std::optional<Distribution1D> distribution_;
    double total_ = 0;
};

}  // namespace isotrace
