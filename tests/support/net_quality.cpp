#include "tests/support/net_quality.h"

#include <bit>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace isotrace::test_support {
namespace {

// Whether each of the 2^(kx+ky) intervals with 2^kx columns and 2^ky rows holds exactly `per_interval` points.
bool intervals_hold_equally(std::span<const std::array<double, 2>> points, int kx, int ky, std::size_t per_interval) {
    std::vector<std::size_t> counts(std::size_t{1} << (kx + ky), 0);
    for (const auto& [x, y] : points) {
        const auto column = static_cast<std::size_t>(x * static_cast<double>(std::size_t{1} << kx));
        const auto row = static_cast<std::size_t>(y * static_cast<double>(std::size_t{1} << ky));
        if (++counts[(row << kx) | column] > per_interval) return false;
    }
    return true;  // no interval exceeds its share and the total matches, so all hold exactly per_interval
}

}  // namespace

int net_t_value(std::span<const std::array<double, 2>> points) {
    if (!std::has_single_bit(points.size())) throw std::invalid_argument("net_t_value: point count not 2^m");
    for (const auto& [x, y] : points) {
        if (!(x >= 0 && x < 1 && y >= 0 && y < 1)) throw std::invalid_argument("net_t_value: point outside [0,1)^2");
    }
    const int m = std::countr_zero(points.size());
    for (int t = 0; t < m; ++t) {
        bool all_shapes = true;
        for (int kx = 0; kx <= m - t && all_shapes; ++kx) {
            all_shapes = intervals_hold_equally(points, kx, m - t - kx, std::size_t{1} << t);
        }
        if (all_shapes) return t;
    }
    return m;
}

}  // namespace isotrace::test_support
