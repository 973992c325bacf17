#include "geometry/superquadric/norm_exponent.h"

#include <map>
#include <mutex>
#include <numbers>
#include <utility>

namespace isotrace {
namespace {

// Whether an interpolant's coefficients are in powers of t ∈ [−1, 1] or of s = (t + 1)/2 ∈ [0, 1].
enum class Basis { Centred, Unit };

// What interpolation at n Chebyshev nodes takes whatever the function: the nodes, the cosines that turn the nodes'
// values into Chebyshev coefficients, and each T_j expanded in powers of t and of s (by T_j = 2t·T_(j−1) − T_(j−2),
// t = 2s − 1). Made once: the cosines are most of an interpolant's cost, and every fractional exponent takes three.
template <std::size_t n>
struct ChebyshevTables {
    using Row = std::array<long double, n>;
    Row nodes{};
    std::array<Row, n> cosines{}, centred{}, unit{};

    ChebyshevTables() {
        constexpr long double pi = std::numbers::pi_v<long double>;
        for (std::size_t k = 0; k < n; ++k) nodes[k] = std::cos(pi * (k + 0.5L) / n);
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t k = 0; k < n; ++k) cosines[j][k] = std::cos(pi * j * (k + 0.5L) / n);
        expand(1, 0, centred);
        expand(2, -1, unit);
    }
    // T_0 … T_(n−1) in powers of v, with t = scale·v + offset.
    static void expand(long double scale, long double offset, std::array<Row, n>& out) {
        Row before{}, current{}, next{};  // T_(j−1), T_j, T_(j+1)
        current[0] = 1;
        for (std::size_t j = 0; j < n; ++j) {
            out[j] = current;
            for (std::size_t i = 0; i < n; ++i) {
                const long double times_t = scale * (i > 0 ? current[i - 1] : 0.0L) + offset * current[i];
                next[i] = (j == 0 ? 1.0L : 2.0L) * times_t - (j == 0 ? 0.0L : before[i]);
            }
            before = current;
            current = next;
        }
    }
    static const ChebyshevTables& get() {
        static const ChebyshevTables tables;
        return tables;
    }
};

// The polynomial that interpolates f over t ∈ [−1, 1] at the Chebyshev nodes, as coefficients in the basis' powers:
// the Chebyshev coefficients from the nodes' values, then the T_j expanded. In long double, so that the expansion's
// cancellations leave the coefficients right to the last bit of a double.
template <std::size_t n, class F>
std::array<double, n> chebyshev_interpolant(const F& f, Basis basis = Basis::Centred) {
    const ChebyshevTables<n>& tables = ChebyshevTables<n>::get();
    const auto& expanded = basis == Basis::Unit ? tables.unit : tables.centred;
    std::array<long double, n> values{}, chebyshev{}, monomial{};
    for (std::size_t k = 0; k < n; ++k) values[k] = f(tables.nodes[k]);
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t k = 0; k < n; ++k) chebyshev[j] += values[k] * tables.cosines[j][k];
        chebyshev[j] *= (j == 0 ? 1.0L : 2.0L) / n;
    }
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) monomial[i] += chebyshev[j] * expanded[j][i];
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

// The tables of exponent p (with its flags set in `e`), made the first time p is asked for and shared while any
// NormExponent holds them. Exponents are made while scenes load; the lock is not on any ray's way.
std::shared_ptr<const NormTables> tables_of(const NormExponent& e) {
    static std::mutex mutex;
    static std::map<double, std::weak_ptr<const NormTables>> made;
    const std::lock_guard lock(mutex);
    std::weak_ptr<const NormTables>& slot = made[e.p];
    if (std::shared_ptr<const NormTables> shared = slot.lock()) return shared;
    auto tables = std::make_shared<NormTables>();
    constexpr std::size_t kTerms = std::tuple_size_v<decltype(tables->root_polynomial)>;
    const long double p = e.p;
    if (!e.has_closed_root())
        tables->root_polynomial =
            chebyshev_interpolant<kTerms>([&](long double t) { return std::pow(1.5L + 0.5L * t, 1 / p); });
    // A function of the mantissa m on one half of [1, 2), as NormExponent::split takes it: in s = 2m − 2 over
    // [1, 1.5] and 2m − 3 over [1.5, 2], both in [0, 1], the terms of the polynomial are then all but its last few of
    // one sign, and their sum loses nothing to cancellation.
    const auto on_half = [&](int half, const auto& f) {
        return chebyshev_interpolant<kTerms>([&](long double t) { return f((t + 5 + 2 * half) / 4); }, Basis::Unit);
    };
    if (e.tabulated) {
        for (int half = 0; half < 2; ++half)
            tables->mantissa_power_polynomials[half] = on_half(half, [&](long double m) { return std::pow(m, p); });
        for (int k = 0; k < NormTables::kOctaves; ++k) tables->octave_powers[k] = double(std::exp2(-k * p));
    }
    if (e.norm_tabulated)
        for (int k = 1; k <= NormTables::kNormOctaves; ++k)
            for (int half = 0; half < 2; ++half)
                tables->norm_polynomials[2 * (k - 1) + half] = on_half(half, [&](long double m) {
                    return std::pow(1 + std::pow(std::ldexp(m, -k), p), 1 / p);
                });
    slot = tables;
    // Entries of exponents no longer held are dropped whenever the map has doubled, so that it keeps to about those
    // in use at a cost that does not grow with their number.
    if ((made.size() & (made.size() - 1)) == 0)
        std::erase_if(made, [](const auto& entry) { return entry.second.expired(); });
    return tables;
}

}  // namespace

NormExponent NormExponent::of_epsilon(double epsilon) {
    const double p = 2 / epsilon;
    NormExponent e{p, p == std::floor(p) && p <= kMaxWhole ? int(p) : 0, 1 / p};
    if (e.whole > 0) e.whole_power = kWholePowers[e.whole - 1];
    e.tabulated = e.whole == 0 && p <= kMostTabulated;
    e.norm_tabulated = e.whole == 0 && p <= kMostNormTabulated;
    if (!e.has_closed_root() || e.tabulated) e.tables = tables_of(e);
    return e;
}

}  // namespace isotrace
