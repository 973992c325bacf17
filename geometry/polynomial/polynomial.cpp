#include "geometry/polynomial/polynomial.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace isotrace {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

}  // namespace

void polynomial_detail::throw_degree_too_high() {
    throw std::length_error("polynomial degree exceeds kMaxPolynomialDegree");
}

Polynomial::Polynomial(std::initializer_list<double> coefficients_low_to_high)
    : Polynomial(std::span<const double>(coefficients_low_to_high.begin(), coefficients_low_to_high.size())) {}

double Polynomial::evaluation_error_bound(double t) const {
    const double magnitude_t = std::abs(t);
    double magnitude = std::abs(coefficients_[degree_]);
    for (int i = degree_ - 1; i >= 0; --i) magnitude = magnitude * magnitude_t + std::abs(coefficients_[i]);
    // 2n for Horner's multiply-adds, doubled to cover coefficients that were themselves computed (products of
    // factors, compositions) rather than given exactly.
    return (4 * degree_ + 2) * kEpsilon * magnitude;
}

bool Polynomial::is_zero_within_rounding(double t) const {
    return std::abs(evaluate(t)) <= evaluation_error_bound(t);
}

Polynomial Polynomial::derivative() const {
    Polynomial result;
    if (degree_ == 0) return result;
    for (int i = 1; i <= degree_; ++i) result.coefficients_[i - 1] = i * coefficients_[i];
    result.degree_ = degree_ - 1;
    return result;
}

Polynomial Polynomial::without_negligible_leading_terms(double a, double b) const {
    const double m = std::max(std::abs(a), std::abs(b));
    std::array<double, kMaxPolynomialDegree + 1> term_magnitudes{};
    double total = 0, power = 1;
    for (int i = 0; i <= degree_; ++i, power *= m) total += term_magnitudes[i] = std::abs(coefficients_[i]) * power;
    Polynomial result = *this;
    while (result.degree_ > 0 && term_magnitudes[result.degree_] <= kEpsilon * total) {
        result.coefficients_[result.degree_] = 0;
        --result.degree_;
    }
    return result;
}

Polynomial Polynomial::normalised() const {
    double largest = 0;
    for (int i = 0; i <= degree_; ++i) largest = std::max(largest, std::abs(coefficients_[i]));
    if (largest == 0 || !std::isfinite(largest)) return *this;
    const int exponent = std::ilogb(largest);
    Polynomial result = *this;
    for (int i = 0; i <= degree_; ++i) result.coefficients_[i] = std::ldexp(coefficients_[i], -exponent);
    return result;
}

Polynomial& Polynomial::operator+=(const Polynomial& other) {
    degree_ = std::max(degree_, other.degree_);
    for (int i = 0; i <= other.degree_; ++i) coefficients_[i] += other.coefficients_[i];
    drop_zero_leading_coefficients();
    return *this;
}

Polynomial& Polynomial::operator-=(const Polynomial& other) {
    degree_ = std::max(degree_, other.degree_);
    for (int i = 0; i <= other.degree_; ++i) coefficients_[i] -= other.coefficients_[i];
    drop_zero_leading_coefficients();
    return *this;
}

Polynomial& Polynomial::operator*=(double factor) {
    for (int i = 0; i <= degree_; ++i) coefficients_[i] *= factor;
    drop_zero_leading_coefficients();
    return *this;
}

Polynomial operator*(const Polynomial& p, const Polynomial& q) {
    if (p.is_zero() || q.is_zero()) return {};
    polynomial_detail::require_degree_fits(static_cast<std::size_t>(p.degree_ + q.degree_));
    Polynomial product;
    product.degree_ = p.degree_ + q.degree_;
    for (int i = 0; i <= p.degree_; ++i)
        for (int j = 0; j <= q.degree_; ++j) product.coefficients_[i + j] += p.coefficients_[i] * q.coefficients_[j];
    product.drop_zero_leading_coefficients();
    return product;
}

Polynomial Polynomial::remainder(const Polynomial& divisor, double relative_noise) const {
    Polynomial quotient;
    return divide(divisor, relative_noise, quotient);
}

Polynomial Polynomial::quotient(const Polynomial& divisor) const {
    Polynomial quotient;
    divide(divisor, 0, quotient);
    return quotient;
}

Polynomial Polynomial::divide(const Polynomial& divisor, double relative_noise, Polynomial& quotient) const {
    Polynomial rest = *this;
    quotient = Polynomial{};
    std::array<double, kMaxPolynomialDegree + 1> largest_term{};
    for (int i = 0; i <= degree_; ++i) largest_term[i] = std::abs(coefficients_[i]);
    const int n = divisor.degree_;
    quotient.degree_ = std::max(degree_ - n, 0);
    for (int top = degree_; top >= n; --top) {
        const double factor = rest.coefficients_[top] / divisor.coefficients_[n];
        quotient.coefficients_[top - n] = factor;
        for (int k = 0; k < n; ++k) {
            const double term = factor * divisor.coefficients_[k];
            rest.coefficients_[top - n + k] -= term;
            largest_term[top - n + k] = std::max(largest_term[top - n + k], std::abs(term));
        }
        rest.coefficients_[top] = 0;
    }
    quotient.drop_zero_leading_coefficients();
    for (int i = 0; i < n; ++i)
        if (std::abs(rest.coefficients_[i]) <= relative_noise * largest_term[i]) rest.coefficients_[i] = 0;
    if (n == 0) rest.coefficients_[0] = 0;
    rest.degree_ = std::min(degree_, std::max(n - 1, 0));
    rest.drop_zero_leading_coefficients();
    return rest;
}

}  // namespace isotrace
