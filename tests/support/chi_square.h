#pragma once
// Pearson chi-square goodness-of-fit testing for statistical tests across the project: compare a histogram
// of generated samples with the counts their claimed density predicts.
#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace isotrace::test_support {

struct ChiSquareResult {
    double statistic = 0;
    int dof = 0;
    double p_value = 1;
};

// Regularized incomplete gamma functions P(a, x) and Q(a, x) = 1 - P(a, x), for a > 0, x >= 0.
double regularized_gamma_p(double a, double x);
double regularized_gamma_q(double a, double x);

// P(X >= statistic) for X ~ chi-square with `dof` degrees of freedom.
double chi_square_p_value(double statistic, int dof);

// Goodness of fit of observed against expected counts per bin (equal-length spans, expected summing to the
// number of samples). Bins expecting fewer than `min_expected` samples are pooled (Mitsuba/pbrt style) so
// the chi-square approximation holds; dof = bins after pooling - 1. A sample in a bin expecting none gives
// p = 0. Throws std::invalid_argument when fewer than two bins remain.
ChiSquareResult chi_square_test(std::span<const double> observed, std::span<const double> expected,
                                double min_expected = 5.0);

// Per-test significance level so that `test_count` independent tests together reject a correct
// hypothesis with probability `family_significance` (Sidak correction).
double sidak_significance(double family_significance, int test_count);

// A rectangular domain split into columns x rows equal cells.
struct Grid2D {
    double x_min, x_max, y_min, y_max;
    int columns, rows;
};

using Point2 = std::array<double, 2>;

struct Histogram2D {
    std::vector<double> counts;  // row-major: cell (column, row) at row * columns + column
    double outside = 0;          // points outside the domain or NaN
};

// Histograms point_of(0) ... point_of(sample_count - 1).
Histogram2D histogram_2d(const Grid2D& grid, std::size_t sample_count,
                         const std::function<Point2(std::size_t)>& point_of);

// sample_count times the integral of `density` over each cell, by nested adaptive Simpson quadrature
// (accurate also for densities with discontinuities inside cells, such as a disk's boundary).
std::vector<double> expected_counts_2d(const Grid2D& grid, std::size_t sample_count,
                                       const std::function<double(double, double)>& density);

// Histograms the points, integrates the density, and tests the fit. Points outside the domain form one
// more bin whose expectation is the probability mass the density leaves outside the grid.
ChiSquareResult chi_square_test_2d(const Grid2D& grid, std::size_t sample_count,
                                   const std::function<Point2(std::size_t)>& point_of,
                                   const std::function<double(double, double)>& density);

}  // namespace isotrace::test_support
