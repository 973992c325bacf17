#include "geometry/implicit/field_function.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "geometry/implicit/field_kernels.h"
#include "geometry/implicit/parameter_check.h"

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

std::span<const std::string_view> field_function_names() { return FieldKernels::kNames; }

namespace {

// A kernel of FieldKernels; `sharpness` goes to those whose constructor takes a parameter (Blinn's).
template <class Kernel>
std::unique_ptr<const FieldFunction> make_kernel(double sharpness) {
    if constexpr (std::is_constructible_v<Kernel, double>) return std::make_unique<Kernel>(sharpness);
    else return std::make_unique<Kernel>();
}

template <class... Kernels>
std::unique_ptr<const FieldFunction> make_listed(KernelList<Kernels...>, std::size_t index, double sharpness) {
    using Make = std::unique_ptr<const FieldFunction> (*)(double);
    static constexpr Make kMake[] = {&make_kernel<Kernels>...};
    return kMake[index](sharpness);
}

}  // namespace

std::unique_ptr<const FieldFunction> make_field_function(std::string_view name, double blinn_sharpness) {
    if (const std::optional<std::size_t> index = field_kernel_index(name))
        return make_listed(FieldKernels{}, *index, blinn_sharpness);
    std::string message = "field: unknown field function \"" + std::string(name) + "\" (expected one of:";
    for (std::string_view known : field_function_names()) message += " " + std::string(known);
    throw std::invalid_argument(message + ")");
}

}  // namespace isotrace
