#pragma once
// Wyvill's soft-object sextic (Wyvill, McPheeters & Wyvill 1986): f = 1 − 22/9·x + 17/9·x² − 4/9·x³ with
// x = r²/R², which factors as (1 − x)²·(9 − 4x)/9; f(R/2) = 1/2. A cubic in r² (degree 6 in t along a ray);
// C¹ at r = R.
#include "geometry/implicit/field_function.h"

namespace isotrace {

class WyvillSextic final : public FieldFunction {
public:
    static constexpr std::string_view kName = "wyvill";
    std::string_view name() const override { return kName; }
    // The factored form keeps full relative accuracy near r = R, where thin blends put their surfaces.
    double unit_value(double x) const override {
        const double u = 1 - x;
        return u * u * (9 - 4 * x) / 9;
    }
    double unit_derivative(double x) const override { return unit_derivative_of(x); }
    // df/dx for a double or for lanes of doubles (as KimSextic's).
    template <class T>
    static T unit_derivative_of(T x) {
        return -(1.0 - x) * (22.0 - 12.0 * x) / 9.0;
    }
    std::span<const FieldPiece> unit_pieces() const override;
    double unit_iso_level(double level) const override;
};

}  // namespace isotrace
