#include "renderer/sampling/distribution_2d.h"

#include <algorithm>
#include <stdexcept>

namespace isotrace {
namespace {

std::vector<Distribution1D> make_rows(std::span<const float> weights, size_t width, size_t height) {
    if (width == 0 || height == 0) throw std::invalid_argument("Distribution2D: empty grid");
    if (weights.size() != width * height) throw std::invalid_argument("Distribution2D: weights do not fill the grid");
    std::vector<Distribution1D> rows;
    rows.reserve(height);
    for (size_t r = 0; r < height; ++r) rows.emplace_back(weights.subspan(r * width, width));
    return rows;
}

std::vector<float> row_integrals(const std::vector<Distribution1D>& rows) {
    std::vector<float> integrals;
    integrals.reserve(rows.size());
    for (const Distribution1D& row : rows) integrals.push_back(row.integral());
    return integrals;
}

}  // namespace

Distribution2D::Distribution2D(std::span<const float> weights, size_t width, size_t height)
    : width_(width), height_(height), rows_(make_rows(weights, width, height)), marginal_(row_integrals(rows_)) {}

Distribution2D::Sample Distribution2D::sample(std::array<float, 2> u) const {
    const Distribution1D::ContinuousSample row = marginal_.sample_continuous(u[1]);
    const Distribution1D::ContinuousSample column = rows_[row.bin].sample_continuous(u[0]);
    return {{column.x, row.x}, row.pdf * column.pdf, column.bin, row.bin};
}

float Distribution2D::pdf(std::array<float, 2> uv) const {
    const auto row = std::min(static_cast<size_t>(std::max(0.0f, uv[1]) * static_cast<float>(height_)), height_ - 1);
    return marginal_.pdf(uv[1]) * rows_[row].pdf(uv[0]);
}

}  // namespace isotrace
