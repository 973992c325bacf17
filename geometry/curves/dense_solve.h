#pragma once
// Solves A·x = b for a small dense square matrix A of numbers and right-hand sides of any vector-space type P
// (double, Vec3d, quaternions, homogeneous points): Gaussian elimination with partial pivoting. Curve
// interpolation uses it; its systems have at most a few hundred unknowns.
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace isotrace {

// `matrix` is row-major, n × n with n = rhs.size(). Throws std::invalid_argument when a pivot is below
// 1e-14 times the largest entry (a singular or numerically singular system).
template <class P>
std::vector<P> solve_dense(std::vector<double> matrix, std::vector<P> rhs) {
    const std::size_t n = rhs.size();
    if (matrix.size() != n * n) throw std::invalid_argument("solve_dense: matrix and right-hand side disagree in size");
    double largest = 0;
    for (double v : matrix) largest = std::max(largest, std::abs(v));
    auto at = [&](std::size_t r, std::size_t c) -> double& { return matrix[r * n + c]; };
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < n; ++r)
            if (std::abs(at(r, col)) > std::abs(at(pivot, col))) pivot = r;
        if (!(std::abs(at(pivot, col)) > 1e-14 * largest)) throw std::invalid_argument("solve_dense: singular system");
        if (pivot != col) {
            for (std::size_t c = 0; c < n; ++c) std::swap(at(pivot, c), at(col, c));
            std::swap(rhs[pivot], rhs[col]);
        }
        for (std::size_t r = col + 1; r < n; ++r) {
            const double factor = at(r, col) / at(col, col);
            if (factor == 0) continue;
            for (std::size_t c = col; c < n; ++c) at(r, c) -= factor * at(col, c);
            rhs[r] = rhs[r] - factor * rhs[col];
        }
    }
    std::vector<P> x(rhs);
    for (std::size_t i = n; i-- > 0;) {
        P sum = rhs[i];
        for (std::size_t c = i + 1; c < n; ++c) sum = sum - at(i, c) * x[c];
        x[i] = (1.0 / at(i, i)) * sum;
    }
    return x;
}

}  // namespace isotrace
