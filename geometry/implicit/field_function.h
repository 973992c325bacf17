#pragma once
// The field function f of a skeletal element (Table 1 of Kim & Kim 2000, MetaCube): density as a function of
// the squared distance r² to the element's skeleton. The field of an element of field radius R and weight w is
// w·f(r²; R); a blob group sums them and its surface is Σ wᵢ·fᵢ − T = 0.
//
// Every kernel here is a profile of x = r²/R² alone, so the shape scales with R, and every kernel is exactly
// zero for r ≥ R: the support radius of an element is its R, whatever the kernel (Blinn's exponential is
// truncated there, see blinn_exponential.h). Working in r² avoids square roots wherever the kernel allows.
//
// Guarantee for root finders (tested for every kernel): f is non-increasing and convex in r² on [0, ∞).
// Hence on an interval r² ∈ [a, b], f lies in [f(b), f(a)] and |df/dr²| ≤ |df/dr²(a)| (a Lipschitz bound).
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string_view>

namespace isotrace {

// A stretch of squared distance on which the kernel has one closed form.
struct FieldPiece {
    double r2_begin = 0, r2_end = 0;  // the piece is r² ∈ [r2_begin, r2_end]
    // True when f is a polynomial in r² here: f = Σₖ coefficients[k]·(r²)ᵏ for k ≤ degree. Along a ray r²(t) is
    // quadratic, so the field is then a polynomial in t. False for Blinn's exponential and for Nishimura's outer
    // piece (quadratic in r, not in r²): use the monotone/convex bounds above instead.
    bool is_polynomial = false;
    int degree = 0;
    std::array<double, 4> coefficients{};  // low to high powers of r²
};

// At most two pieces (Nishimura splits at r = R/3), covering r² ∈ [0, R²]; f = 0 beyond.
struct FieldPieces {
    std::array<FieldPiece, 2> pieces{};
    int count = 0;
    std::span<const FieldPiece> span() const& { return {pieces.data(), std::size_t(count)}; }
    // A span of a temporary dangles at the end of the full expression (`for (p : f.pieces(R).span())`, found
    // twice by AddressSanitizer in tests): keep the pieces in a variable.
    std::span<const FieldPiece> span() const&& = delete;
};

class FieldFunction {
public:
    virtual ~FieldFunction() = default;

    // The scene name (the concrete class's kName, field_kernels.h).
    virtual std::string_view name() const = 0;

    // f and df/d(r²) at squared distance r2 ≥ 0 from an element of field radius R > 0; both 0 for r2 ≥ R².
    double value(double r2, double radius) const { return kernel_value(*this, r2, radius); }
    double derivative(double r2, double radius) const { return kernel_derivative(*this, r2, radius); }
    // The same for a kernel given as its concrete (final) class, whose unit profile then inlines: the blob
    // group's hot loops call these once per element.
    template <class Kernel>
    static double kernel_value(const Kernel& kernel, double r2, double radius) {
        const double x = r2 / (radius * radius);
        return x < 1 ? kernel.unit_value(x) : 0;
    }
    template <class Kernel>
    static double kernel_derivative(const Kernel& kernel, double r2, double radius) {
        const double inverse_radius2 = 1 / (radius * radius);  // one division, not two (every blob hit's normal)
        const double x = r2 * inverse_radius2;
        return x < 1 ? kernel.unit_derivative(x) * inverse_radius2 : 0;
    }

    // The kernel's closed forms over [0, R²], with polynomial coefficients scaled to powers of r² (R > 0).
    FieldPieces pieces(double radius) const;

    // The distance r at which a lone element reaches the threshold, w·f(r) = T: its isosurface is the set of
    // points at distance r from the skeleton (a sphere for a metaball, a rounded box for a metacube).
    // std::nullopt when w ≤ T (the field never exceeds T). Throws std::invalid_argument for a threshold that is
    // not finite and > 0, a radius that is not finite and ≥ 0, or a weight that is not finite.
    std::optional<double> iso_radius(double radius, double weight, double threshold) const;

    // The same kernel on the unit support: x = r²/R² ∈ [0, 1). Public so tests and plots can read the profile.
    virtual double unit_value(double x) const = 0;
    virtual double unit_derivative(double x) const = 0;  // df/dx
    // The pieces on x ∈ [0, 1] with coefficients in powers of x.
    virtual std::span<const FieldPiece> unit_pieces() const = 0;
    // The x where unit_value(x) = level, for a level in (0, 1).
    virtual double unit_iso_level(double level) const = 0;
};

// Throws std::invalid_argument naming "threshold" unless T is finite and > 0.
void validate_threshold(double threshold);

// The names make_field_function accepts: those of FieldKernels (field_kernels.h), in its order.
std::span<const std::string_view> field_function_names();

// The kernel called `name` (see field_function_names). `blinn_sharpness` is used by "blinn" only. Throws
// std::invalid_argument naming "field" for an unknown name, or "sharpness" for an invalid sharpness.
std::unique_ptr<const FieldFunction> make_field_function(std::string_view name, double blinn_sharpness);

}  // namespace isotrace
