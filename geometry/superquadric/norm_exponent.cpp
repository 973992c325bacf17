#include "geometry/superquadric/norm_exponent.h"

#include <numbers>
#include <utility>

namespace isotrace {
namespace {

// The coefficients, in powers of t ∈ [−1, 1], of the polynomial that interpolates f at the Chebyshev nodes: the
// Chebyshev coefficients from the nodes' values, then T_j expanded by T_j = 2t·T_(j−1) − T_(j−2). In long double, so
// that the expansion's cancellations leave the coefficients right to the last bit of a double.
template <std::size_t n, class F>
std::array<double, n> chebyshev_interpolant(const F& f) {
    constexpr long double pi = std::numbers::pi_v<long double>;
    std::array<long double, n> values{}, chebyshev{}, monomial{};
    for (std::size_t k = 0; k < n; ++k) values[k] = f(std::cos(pi * (k + 0.5L) / n));
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t k = 0; k < n; ++k) chebyshev[j] += values[k] * std::cos(pi * j * (k + 0.5L) / n);
        chebyshev[j] *= (j == 0 ? 1.0L : 2.0L) / n;
    }
    std::array<long double, n> before{}, current{}, next{};  // T_(j−1), T_j, T_(j+1) in powers of t
    current[0] = 1;
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t i = 0; i < n; ++i) monomial[i] += chebyshev[j] * current[i];
        for (std::size_t i = 0; i < n; ++i)
            next[i] = (j == 0 ? 1.0L : 2.0L) * (i > 0 ? current[i - 1] : 0.0L) - (j == 0 ? 0.0L : before[i]);
        before = current;
        current = next;
    }
    std::array<double, n> rounded{};
    for (std::size_t i = 0; i < n; ++i) rounded[i] = double(monomial[i]);
    return rounded;
}

// x^n by repeated squaring, its multiplications unrolled at compile time (a loop over n's bits costs several
// times the multiplications).
template <int n>
double power_of(double x) {
    if constexpr (n == 1) return x;
    else if constexpr (n % 2 == 1) return x * power_of<n - 1>(x);
    else {
        const double half = power_of<n / 2>(x);
        return half * half;
    }
}

constexpr int kMaxWhole = 64;

template <int... n>
constexpr std::array<double (*)(double), sizeof...(n)> powers_of(std::integer_sequence<int, n...>) {
    return {&power_of<n + 1>...};
}

constexpr auto kWholePowers = powers_of(std::make_integer_sequence<int, kMaxWhole>());  // x^1 to x^64

}  // namespace

NormExponent NormExponent::of_epsilon(double epsilon) {
    const double p = 2 / epsilon;
    NormExponent e{p, p == std::floor(p) && p <= kMaxWhole ? int(p) : 0, 1 / p};
    if (e.whole > 0) e.whole_power = kWholePowers[e.whole - 1];
    if (!e.has_closed_root())
        e.root_polynomial = chebyshev_interpolant<std::tuple_size_v<decltype(root_polynomial)>>(
            [&](long double t) { return std::pow(1.5L + 0.5L * t, 1.0L / e.p); });
    return e;
}

}  // namespace isotrace
