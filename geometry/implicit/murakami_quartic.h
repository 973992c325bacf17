#pragma once
// Murakami's quartic (Murakami & Ichihara 1987): f = (1 − x)², x = r²/R². A quadratic in r² (degree 4 in t
// along a ray); C¹ at r = R.
#include "geometry/implicit/field_function.h"

namespace isotrace {

class MurakamiQuartic final : public FieldFunction {
public:
    static constexpr std::string_view kName = "murakami";
    std::string_view name() const override { return kName; }
    double unit_value(double x) const override {
        const double u = 1 - x;
        return u * u;
    }
    double unit_derivative(double x) const override { return unit_derivative_of(x); }
    // df/dx for a double or for lanes of doubles (as KimSextic's).
    template <class T>
    static T unit_derivative_of(T x) {
        return -2.0 * (1.0 - x);
    }
    std::span<const FieldPiece> unit_pieces() const override;
    double unit_iso_level(double level) const override;
};

}  // namespace isotrace
