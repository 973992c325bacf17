#pragma once
// A real polynomial of bounded degree in double precision, stored in a fixed array so that root finders can
// build derivatives and reparametrisations on the stack (no heap, cheap to copy).
#include <algorithm>
#include <array>
#include <initializer_list>
#include <span>

namespace isotrace {

// The largest degree any Polynomial can have. Field polynomials of the metaball kernels reach 6; 10 leaves room.
inline constexpr int kMaxPolynomialDegree = 10;

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
    explicit Polynomial(std::span<const double> coefficients_low_to_high);
    // leading · ∏(t − rᵢ). Throws std::length_error for more than kMaxPolynomialDegree roots.
    static Polynomial from_roots(std::span<const double> roots, double leading = 1);

    // The stored degree. Arithmetic drops leading coefficients that are exactly zero, so after it this is the
    // true degree; coefficients that are merely tiny are kept (see without_negligible_leading_terms).
    int degree() const { return degree_; }
    double operator[](int power) const { return coefficients_[power]; }
    double leading_coefficient() const { return coefficients_[degree_]; }
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
    // Euclidean division: returns the remainder (noise-cleaned as in remainder()) and stores the quotient.
    Polynomial divide(const Polynomial& divisor, double relative_noise, Polynomial& quotient) const;

    std::array<double, kMaxPolynomialDegree + 1> coefficients_{};
    int degree_ = 0;
};

// The operations of the blob sweep's inner loops and its root refinement, inline so that they fold into their
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
    // Horner's scheme on polynomials: result = (...(cₙ·s + cₙ₋₁)·s + ...) with s = offset + scale·u. Each step
    // updates the coefficients upwards, carrying the old lower one in a register: the downward loop was vectorised
    // into 16-byte loads of pairs the step before had stored one by one, each waiting for those stores (a failed
    // store forwarding: 9 % of the blob sweep's samples, perf). Same operations, same bits.
    Polynomial result;
    double* c = result.coefficients_.data();
    c[0] = coefficients_[degree_];
    for (int i = degree_ - 1; i >= 0; --i) {
        const int top = result.degree_ + 1;  // its old coefficient is 0
        double lower = c[0];
        c[0] = c[0] * offset + coefficients_[i];
        for (int k = 1; k < top; ++k) {
            const double old = c[k];
            c[k] = old * offset + lower * scale;
            lower = old;
        }
        c[top] = 0.0 * offset + lower * scale;
        ++result.degree_;
    }
    result.drop_zero_leading_coefficients();
    return result;
}

inline void Polynomial::drop_zero_leading_coefficients() {
    while (degree_ > 0 && coefficients_[degree_] == 0) --degree_;
}

}  // namespace isotrace
