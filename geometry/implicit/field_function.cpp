#include "geometry/implicit/field_function.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/implicit/blinn_exponential.h"
#include "geometry/implicit/kim_sextic.h"
#include "geometry/implicit/murakami_quartic.h"
#include "geometry/implicit/nishimura_quadratic.h"
#include "geometry/implicit/parameter_check.h"
#include "geometry/implicit/wyvill_sextic.h"

namespace isotrace {

FieldPieces FieldFunction::pieces(double radius) const {
    const double radius2 = radius * radius;
    FieldPieces scaled;
    for (const FieldPiece& unit : unit_pieces()) {
        FieldPiece piece = unit;
        piece.r2_begin = unit.r2_begin * radius2;
        piece.r2_end = unit.r2_end * radius2;
        double power = 1;  // R^(2k): a coefficient of xᵏ becomes one of (r²)ᵏ
        for (int k = 0; k <= unit.degree; ++k, power *= radius2) piece.coefficients[k] = unit.coefficients[k] / power;
        scaled.pieces[scaled.count++] = piece;
    }
    return scaled;
}

std::optional<double> FieldFunction::iso_radius(double radius, double weight, double threshold) const {
    validate_threshold(threshold);
    require_parameter(std::isfinite(radius) && radius >= 0, "radius", "must be finite and >= 0", radius);
    require_parameter(std::isfinite(weight), "weight", "must be finite", weight);
    if (weight <= threshold) return std::nullopt;
    return radius * std::sqrt(unit_iso_level(threshold / weight));
}

void validate_threshold(double threshold) {
    require_parameter(std::isfinite(threshold) && threshold > 0, "threshold", "must be finite and > 0", threshold);
}

std::span<const std::string_view> field_function_names() {
    static constexpr std::array<std::string_view, 5> names = {"blinn", "nishimura", "murakami", "wyvill", "kim"};
    return names;
}

std::unique_ptr<const FieldFunction> make_field_function(std::string_view name, double blinn_sharpness) {
    if (name == "blinn") return std::make_unique<BlinnExponential>(blinn_sharpness);
    if (name == "nishimura") return std::make_unique<NishimuraQuadratic>();
    if (name == "murakami") return std::make_unique<MurakamiQuartic>();
    if (name == "wyvill") return std::make_unique<WyvillSextic>();
    if (name == "kim") return std::make_unique<KimSextic>();
    std::string message = "field: unknown field function \"" + std::string(name) + "\" (expected one of:";
    for (std::string_view known : field_function_names()) message += " " + std::string(known);
    throw std::invalid_argument(message + ")");
}

}  // namespace isotrace
