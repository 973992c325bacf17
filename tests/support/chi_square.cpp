#include "tests/support/chi_square.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace isotrace::test_support {
namespace {

constexpr int kMaxIterations = 10000;
constexpr double kRelativeTolerance = 1e-15;

// x^a e^-x / Gamma(a), the common prefactor of both expansions, evaluated in log space to avoid overflow.
double gamma_prefactor(double a, double x) {
    return std::exp(a * std::log(x) - x - std::lgamma(a));
}

// P(a, x) = x^a e^-x / Gamma(a+1) * sum_n x^n / ((a+1)...(a+n)); converges quickly for x < a + 1.
double gamma_p_series(double a, double x) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < kMaxIterations; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * kRelativeTolerance) break;
    }
    return sum * gamma_prefactor(a, x);
}

// Q(a, x) by Legendre's continued fraction, evaluated with the modified Lentz method; converges quickly
// for x >= a + 1.
double gamma_q_continued_fraction(double a, double x) {
    constexpr double tiny = std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon();
    double b = x + 1.0 - a;
    double c = 1.0 / tiny;
    double d = 1.0 / b;
    double fraction = d;
    for (int n = 1; n < kMaxIterations; ++n) {
        const double an = -n * (n - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        fraction *= delta;
        if (std::abs(delta - 1.0) < kRelativeTolerance) break;
    }
    return fraction * gamma_prefactor(a, x);
}

void check_gamma_arguments(double a, double x) {
    if (!(a > 0) || !(x >= 0)) throw std::invalid_argument("incomplete gamma needs a > 0 and x >= 0");
}

// Adaptive Simpson on [a, b] given f at a, the midpoint and b; `whole` is Simpson's estimate on [a, b].
double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm,
                        double fb, double whole, double tolerance, int depth) {
    const double m = 0.5 * (a + b);
    const double left_mid = f(0.5 * (a + m));
    const double right_mid = f(0.5 * (m + b));
    const double left = (m - a) / 6.0 * (fa + 4.0 * left_mid + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * right_mid + fb);
    const double refined = left + right;
    if (depth <= 0 || std::abs(refined - whole) <= 15.0 * tolerance) return refined + (refined - whole) / 15.0;
    return adaptive_simpson(f, a, m, fa, left_mid, fm, left, 0.5 * tolerance, depth - 1) +
           adaptive_simpson(f, m, b, fm, right_mid, fb, right, 0.5 * tolerance, depth - 1);
}

double integrate(const std::function<double(double)>& f, double a, double b, double tolerance) {
    constexpr int max_depth = 12;  // bounds the work when a discontinuity keeps the error estimate high
    const double fa = f(a), fm = f(0.5 * (a + b)), fb = f(b);
    const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    return adaptive_simpson(f, a, b, fa, fm, fb, whole, tolerance, max_depth);
}

}  // namespace

double regularized_gamma_p(double a, double x) {
    check_gamma_arguments(a, x);
    if (x == 0) return 0;
    return x < a + 1.0 ? gamma_p_series(a, x) : 1.0 - gamma_q_continued_fraction(a, x);
}

double regularized_gamma_q(double a, double x) {
    check_gamma_arguments(a, x);
    if (x == 0) return 1;
    return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_continued_fraction(a, x);
}

double chi_square_p_value(double statistic, int dof) {
    if (dof < 1) throw std::invalid_argument("chi-square needs at least one degree of freedom");
    return regularized_gamma_q(0.5 * dof, 0.5 * std::max(0.0, statistic));
}

ChiSquareResult chi_square_test(std::span<const double> observed, std::span<const double> expected,
                                double min_expected) {
    if (observed.size() != expected.size()) throw std::invalid_argument("chi-square: bin counts differ");

    // Visit bins by increasing expectation so the pool collects exactly the sparse ones (stable: ties pool
    // in index order, so results do not depend on the sort implementation).
    std::vector<std::size_t> order(expected.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return expected[i] < expected[j]; });

    struct Bin {
        double observed, expected;
    };
    std::vector<Bin> bins;
    Bin pool{0, 0};
    for (std::size_t i : order) {
        if (expected[i] <= 0) {
            if (observed[i] > 0) return {std::numeric_limits<double>::infinity(), 0, 0.0};
            continue;
        }
        if (expected[i] < min_expected || (pool.expected > 0 && pool.expected < min_expected)) {
            // Too sparse on its own, or the pool is still too sparse and absorbs the next-smallest bin.
            pool.observed += observed[i];
            pool.expected += expected[i];
            if (pool.expected >= min_expected) {
                bins.push_back(pool);
                pool = {0, 0};
            }
        } else {
            bins.push_back({observed[i], expected[i]});
        }
    }
    if (pool.expected > 0) {
        // A leftover pool below the threshold joins the first (smallest) accepted bin, or stands alone if none.
        if (bins.empty()) {
            bins.push_back(pool);
        } else {
            bins.front().observed += pool.observed;
            bins.front().expected += pool.expected;
        }
    }
    if (bins.size() < 2) throw std::invalid_argument("chi-square: fewer than two bins after pooling");

    ChiSquareResult result;
    for (const Bin& bin : bins) {
        const double difference = bin.observed - bin.expected;
        result.statistic += difference * difference / bin.expected;
    }
    result.dof = static_cast<int>(bins.size()) - 1;
    result.p_value = chi_square_p_value(result.statistic, result.dof);
    return result;
}

double sidak_significance(double family_significance, int test_count) {
    return 1.0 - std::pow(1.0 - family_significance, 1.0 / test_count);
}

Histogram2D histogram_2d(const Grid2D& grid, std::size_t sample_count,
                         const std::function<Point2(std::size_t)>& point_of) {
    Histogram2D histogram;
    histogram.counts.assign(static_cast<std::size_t>(grid.columns) * grid.rows, 0.0);
    const double x_scale = grid.columns / (grid.x_max - grid.x_min);
    const double y_scale = grid.rows / (grid.y_max - grid.y_min);
    for (std::size_t i = 0; i < sample_count; ++i) {
        const auto [x, y] = point_of(i);
        // Written so that NaN fails the comparisons and lands outside.
        if (!(x >= grid.x_min && x < grid.x_max && y >= grid.y_min && y < grid.y_max)) {
            histogram.outside += 1;
            continue;
        }
        const int column = std::min(static_cast<int>((x - grid.x_min) * x_scale), grid.columns - 1);
        const int row = std::min(static_cast<int>((y - grid.y_min) * y_scale), grid.rows - 1);
        histogram.counts[static_cast<std::size_t>(row) * grid.columns + column] += 1;
    }
    return histogram;
}

std::vector<double> expected_counts_2d(const Grid2D& grid, std::size_t sample_count,
                                       const std::function<double(double, double)>& density) {
    const double cell_width = (grid.x_max - grid.x_min) / grid.columns;
    const double cell_height = (grid.y_max - grid.y_min) / grid.rows;
    // Absolute tolerance per cell in probability; far below one sample's worth for any practical count.
    const double tolerance = 1e-3 / static_cast<double>(sample_count) / (grid.columns * grid.rows);
    std::vector<double> expected(static_cast<std::size_t>(grid.columns) * grid.rows);
    for (int row = 0; row < grid.rows; ++row) {
        const double y0 = grid.y_min + row * cell_height;
        for (int column = 0; column < grid.columns; ++column) {
            const double x0 = grid.x_min + column * cell_width;
            const auto inner = [&](double x) {
                return integrate([&](double y) { return density(x, y); }, y0, y0 + cell_height,
                                 tolerance / cell_width);
            };
            const double probability = integrate(inner, x0, x0 + cell_width, tolerance);
            expected[static_cast<std::size_t>(row) * grid.columns + column] = probability * sample_count;
        }
    }
    return expected;
}

ChiSquareResult chi_square_test_2d(const Grid2D& grid, std::size_t sample_count,
                                   const std::function<Point2(std::size_t)>& point_of,
                                   const std::function<double(double, double)>& density) {
    Histogram2D histogram = histogram_2d(grid, sample_count, point_of);
    std::vector<double> expected = expected_counts_2d(grid, sample_count, density);
    const double expected_inside = std::accumulate(expected.begin(), expected.end(), 0.0);
    // A residual below a hundredth of a sample is quadrature error, not mass the density puts outside; rounding
    // it to zero makes any point outside an outright failure.
    const double expected_outside = static_cast<double>(sample_count) - expected_inside;
    histogram.counts.push_back(histogram.outside);
    expected.push_back(expected_outside < 0.01 ? 0.0 : expected_outside);
    return chi_square_test(histogram.counts, expected);
}

}  // namespace isotrace::test_support
