#pragma once
// Kim's sextic (Kim & Kim 1996), the kernel the MetaCube paper renders with: f = (1 − x)³, x = r²/R².
// A cubic in r² (degree 6 in t along a ray); C² at r = R.
#include "geometry/implicit/field_function.h"

namespace isotrace {

class KimSextic final : public FieldFunction {
public:
    static constexpr std::string_view kName = "kim";
    std::string_view name() const override { return kName; }
    double unit_value(double x) const override {
        const double u = 1 - x;
        return u * u * u;
    }
    double unit_derivative(double x) const override { return unit_derivative_of(x); }
    // df/dx for a double or for lanes of doubles (double4.h: the blob march's normal sums four elements at a time),
    // with the same operations, so the same bits.
    template <class T>
    static T unit_derivative_of(T x) {
        const T u = 1.0 - x;
        return -3.0 * u * u;
    }
    std::span<const FieldPiece> unit_pieces() const override;
    double unit_iso_level(double level) const override;
};

}  // namespace isotrace
