#pragma once
// Nishimura's piecewise quadratic metaball kernel (Table 1 of the MetaCube paper), with s = r/R, x = r²/R²:
//   f = 1 − 3s²          for s < 1/3   (linear in r², so quadratic in t along a ray)
//   f = 3/2·(1 − s)²     for 1/3 ≤ s ≤ 1
// The pieces meet with equal value (2/3) and slope at s = 1/3 (C¹) and f is C¹ at R. The outer piece is a
// quadratic in r, not in r²: along a ray it contains sqrt(r²(t)), so it is not a polynomial in t and is marked
// non-polynomial (root finders use the monotone/convex bounds of field_function.h on it).
#include <cmath>

#include "geometry/implicit/field_function.h"

namespace isotrace {

class NishimuraQuadratic final : public FieldFunction {
public:
    // x = r²/R² where the two pieces meet (r = R/3).
    static constexpr double kUnitBreakpoint = 1.0 / 9;

    static constexpr std::string_view kName = "nishimura";
    std::string_view name() const override { return kName; }
    double unit_value(double x) const override {
        if (x < kUnitBreakpoint) return 1 - 3 * x;
        const double u = 1 - std::sqrt(x);
        return 1.5 * u * u;
    }
    // d/dx of 3/2·(1 − √x)² is −3/2·(1 − √x)/√x; √x ≥ 1/3 on the outer piece, so no division by zero.
    double unit_derivative(double x) const override {
        if (x < kUnitBreakpoint) return -3;
        const double s = std::sqrt(x);
        return -1.5 * (1 - s) / s;
    }
    std::span<const FieldPiece> unit_pieces() const override;
    double unit_iso_level(double level) const override;
};

}  // namespace isotrace
