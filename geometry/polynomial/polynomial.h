#pragma once
// A real polynomial of bounded degree in double precision, stored in a fixed array so that root finders can
// build derivatives and reparametrisations on the stack (no heap, cheap to copy).
#include <algorithm>
#include <array>
#include <initializer_list>
#include <span>

#include "renderer/math/double4.h"

namespace isotrace {

// The largest degree any Polynomial can have. Field polynomials of the metaball kernels reach 6; 10 leaves room.
inline constexpr int kMaxPolynomialDegree = 10;

// Lanes of four doubles (double4.h) that hold every coefficient of any Polynomial.
inline constexpr int kCoefficientQuads = (kMaxPolynomialDegree + 4) / 4;

// f.template operator()<kQuads>() with the fewest lanes of four that hold the coefficients 0 … degree: the lane code
// on coefficients (compose_linear, the Bernstein test) does no work for the lanes a low degree leaves empty.
template <class F>
[[gnu::always_inline]] inline decltype(auto) with_coefficient_quads(int degree, F&& f) {
    if (degree < 4) return f.template operator()<1>();
    if (degree < 8) return f.template operator()<2>();
    return f.template operator()<kCoefficientQuads>();
}

namespace polynomial_detail {
[[noreturn]] void throw_degree_too_high();  // std::length_error
inline void require_degree_fits(std::size_t degree) {
    if (degree > static_cast<std::size_t>(kMaxPolynomialDegree)) throw_degree_too_high();
}
}  // namespace polynomial_detail

struct ValueAndDerivative {
    double value;
    double derivative;
};

class Polynomial {
public:
    // The zero polynomial (degree 0).
    Polynomial() = default;
    // Coefficients from low to high powers: {c0, c1, c2} is c0 + c1 t + c2 t². Throws std::length_error when
    // there are more than kMaxPolynomialDegree + 1 of them.
    Polynomial(std::initializer_list<double> coefficients_low_to_high);
    explicit Polynomial(std::span<const double> coefficients_low_to_high) {
        if (coefficients_low_to_high.empty()) return;
        polynomial_detail::require_degree_fits(coefficients_low_to_high.size() - 1);
        std::copy(coefficients_low_to_high.begin(), coefficients_low_to_high.end(), coefficients_.begin());
        degree_ = static_cast<int>(coefficients_low_to_high.size()) - 1;
        drop_zero_leading_coefficients();
    }

    // The stored degree. Arithmetic drops leading coefficients that are exactly zero, so after it this is the
    // true degree; coefficients that are merely tiny are kept (see without_negligible_leading_terms).
    int degree() const { return degree_; }
    double operator[](int power) const { return coefficients_[power]; }
    bool is_zero() const { return degree_ == 0 && coefficients_[0] == 0; }

    double evaluate(double t) const;
    ValueAndDerivative evaluate_with_derivative(double t) const;
    // A bound on the rounding error of evaluate(t): γ·Σ|cᵢ||t|ⁱ with γ covering Horner's 2·degree operations
    // and the rounding of the coefficients themselves.
    double evaluation_error_bound(double t) const;
    // True when |p(t)| is within evaluation_error_bound(t), i.e. the sign of p(t) cannot be trusted.
    bool is_zero_within_rounding(double t) const;

    Polynomial derivative() const;
    // q(u) = p(offset + scale·u). With offset = a and scale = b − a this maps u ∈ [0,1] onto t ∈ [a,b].
    Polynomial compose_linear(double offset, double scale) const;
    // p with leading terms dropped while they cannot change the value on [a,b] beyond rounding
    // (|cₙ|·Mⁿ ≤ ε·Σ|cᵢ|Mⁱ, M = max(|a|,|b|)). A nearly vanishing leading coefficient only moves a root far
    // outside the interval, but it would make Sturm remainders and Newton steps ill-conditioned.
    Polynomial without_negligible_leading_terms(double a, double b) const;
    // The same polynomial scaled by a power of two (exact) so that its largest coefficient magnitude lies in
    // [1, 2): signs and roots are unchanged, and chains of divisions can neither overflow nor underflow.
    Polynomial normalised() const;

    Polynomial& operator+=(const Polynomial& other);
    Polynomial& operator-=(const Polynomial& other);
    Polynomial& operator*=(double factor);
    friend Polynomial operator+(Polynomial p, const Polynomial& q) { return p += q; }
    friend Polynomial operator-(Polynomial p, const Polynomial& q) { return p -= q; }
    friend Polynomial operator*(Polynomial p, double factor) { return p *= factor; }
    friend Polynomial operator*(double factor, Polynomial p) { return p *= factor; }
    // Throws std::length_error when the product's degree would exceed kMaxPolynomialDegree.
    friend Polynomial operator*(const Polynomial& p, const Polynomial& q);

    // Remainder of Euclidean division by `divisor` (whose leading coefficient must be non-zero). A remainder
    // coefficient is set to exactly zero when it is ≤ relative_noise times the largest term summed into it: it is
    // then cancellation noise, and treating it as zero is what lets Sturm sequences see multiple roots.
    Polynomial remainder(const Polynomial& divisor, double relative_noise = 0) const;
    // Quotient of the same division (the remainder is dropped).
    Polynomial quotient(const Polynomial& divisor) const;

private:
    void drop_zero_leading_coefficients();
    // compose_linear with the coefficients in kQuads lanes of four (4·kQuads > degree).
    template <int kQuads>
    Polynomial compose_linear_in_quads(double offset, double scale) const;
    // Euclidean division: returns the remainder (noise-cleaned as in remainder()) and stores the quotient.
    Polynomial divide(const Polynomial& divisor, double relative_noise, Polynomial& quotient) const;

    std::array<double, kMaxPolynomialDegree + 1> coefficients_{};
    int degree_ = 0;
};

// The operations of the blob march's inner loops and its root refinement, inline so that they fold into their
// callers.
inline double Polynomial::evaluate(double t) const {
    double value = coefficients_[degree_];
    for (int i = degree_ - 1; i >= 0; --i) value = value * t + coefficients_[i];
    return value;
}

inline ValueAndDerivative Polynomial::evaluate_with_derivative(double t) const {
    double value = coefficients_[degree_];
    double derivative = 0;
    for (int i = degree_ - 1; i >= 0; --i) {
        derivative = derivative * t + value;
        value = value * t + coefficients_[i];
    }
    return {value, derivative};
}

inline Polynomial Polynomial::compose_linear(double offset, double scale) const {
    return with_coefficient_quads(
        degree_, [&]<int kQuads>() { return compose_linear_in_quads<kQuads>(offset, scale); });
}

template <int kQuads>
Polynomial Polynomial::compose_linear_in_quads(double offset, double scale) const {
    // Horner's scheme on polynomials: result = (...(cₙ·s + cₙ₋₁)·s + ...) with s = offset + scale·u, every
    // coefficient of a step at once in lanes of four: cₖ ← cₖ·offset + cₖ₋₁·scale (the coefficients above the
    // degree so far are 0 and stay 0), and c₀ ← c₀·offset + aᵢ. The scalar scheme's operations, so its bits.
    static_assert(kQuads <= kCoefficientQuads, "lanes beyond the coefficient array");
    Double4 c[kQuads] = {};
    c[0][0] = coefficients_[degree_];
    for (int i = degree_ - 1; i >= 0; --i) {
        Double4 next[kQuads];
        // Each coefficient's lower neighbour, one lane up (lane 0 of the first quad is overwritten below).
        next[0] = c[0] * offset + __builtin_shufflevector(c[0], c[0], 0, 0, 1, 2) * scale;
        for (int q = 1; q < kQuads; ++q)
            next[q] = c[q] * offset + __builtin_shufflevector(c[q - 1], c[q], 3, 4, 5, 6) * scale;
        next[0][0] = c[0][0] * offset + coefficients_[i];
        for (int q = 0; q < kQuads; ++q) c[q] = next[q];
    }
    Polynomial result;
    for (int k = 0; k <= degree_; ++k) result.coefficients_[std::size_t(k)] = c[k / 4][k % 4];
    result.degree_ = degree_;
    result.drop_zero_leading_coefficients();
    return result;
}

inline void Polynomial::drop_zero_leading_coefficients() {
    while (degree_ > 0 && coefficients_[degree_] == 0) --degree_;
}

}  // namespace isotrace
