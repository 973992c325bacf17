#pragma once
// Piecewise-constant distribution over [0,1)^2 proportional to a grid of non-negative weights (e.g. the
// texels of an environment map): a marginal distribution picks the row, then that row's conditional
// distribution picks the column (both Distribution1D).
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "renderer/sampling/distribution_1d.h"

namespace isotrace {

class Distribution2D {
public:
    struct Sample {
        std::array<float, 2> uv;  // in [0,1)^2; uv[0] along a row (column coordinate), uv[1] across rows
        float pdf;                // density at uv with respect to du dv
        size_t column, row;       // the cell containing uv
    };

    // `weights` row-major: `width` columns per row, `height` rows; row r covers uv[1] in [r, r+1) / height.
    // Throws std::invalid_argument when the sizes do not match or a weight is negative, infinite or NaN.
    // All-zero weights give the uniform distribution (like Distribution1D).
    Distribution2D(std::span<const float> weights, size_t width, size_t height);

    // u[1] picks the row, u[0] the column within it (each through its distribution's continuous sample, so
    // strata of u stay strata of uv within a cell). Cells of zero weight are never returned.
    Sample sample(std::array<float, 2> u) const;
    // Density at uv in [0,1)^2: weight(cell) * width * height / sum of weights.
    float pdf(std::array<float, 2> uv) const;

    size_t width() const { return width_; }
    size_t height() const { return height_; }

private:
    size_t width_, height_;
    std::vector<Distribution1D> rows_;  // conditional distribution of the column, per row
    Distribution1D marginal_;           // over rows, weighted by each row's integral
};

}  // namespace isotrace
