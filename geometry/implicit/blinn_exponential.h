#pragma once
// Blinn's exponential "blobby" kernel (Blinn 1982), e^(−a·r²), truncated to the element's field radius R so that
// every kernel has the same finite support (bounds, the element hierarchy and ray pieces all rely on it).
//
// Truncation: with x = r²/R² and a dimensionless sharpness a (Blinn's own a is a/R²), the kernel is
//   f = (e^(−a·x) − e^(−a)) / (1 − e^(−a))
// i.e. the value at the cut is subtracted, so f is continuous and zero at r = R, and the result is rescaled so
// that f(0) = 1 and w stays the density at the skeleton, as for the other kernels. The slope does not vanish at
// the cut: f is C⁰ but not C¹ at r = R (a kink of size a·e^(−a)/(1 − e^(−a)) in df/dx). For a ≳ 8 the change
// from the raw exponential is below 3.4e-4. iso_radius inverts this truncated form exactly.
//
// Not a polynomial: root finders use the monotone/convex bounds documented in field_function.h.
#include <cmath>

#include "geometry/implicit/field_function.h"

namespace isotrace {

class BlinnExponential final : public FieldFunction {
public:
    // a = 3 falls off like Kim's (1 − x)³ near the skeleton (both ≈ 1 − 3x).
    static constexpr double kDefaultSharpness = 3;

    // Throws std::invalid_argument naming "sharpness" unless a is finite and > 0.
    explicit BlinnExponential(double sharpness);

    double sharpness() const { return sharpness_; }

    static constexpr std::string_view kName = "blinn";
    std::string_view name() const override { return kName; }
    double unit_value(double x) const override {
        return std::exp(-sharpness_ * x) * std::expm1(-sharpness_ * (1 - x)) / expm1_minus_a_;
    }
    double unit_derivative(double x) const override {
        return sharpness_ * std::exp(-sharpness_ * x) / expm1_minus_a_;
    }
    std::span<const FieldPiece> unit_pieces() const override;
    double unit_iso_level(double level) const override;

private:
    double sharpness_;
    double expm1_minus_a_;  // e^(−a) − 1 = −(1 − e^(−a)), the normalisation, computed without cancellation
};

}  // namespace isotrace
