#include "geometry/isosurface/linear_cell_bound.h"

namespace isotrace {

LinearCellBound LinearCellBound::of(const ImplicitField& field, const IntervalBox& cell) {
    LinearCellBound model;
    model.centre = (cell.lower() + cell.upper()) * 0.5;
    const double f = field.value(model.centre);
    model.gradient = field.gradient(model.centre);
    const Vec3d half = (cell.upper() - cell.lower()) * 0.5;
    double scale = std::abs(f);
    model.gradient_range = field.gradient_range(cell);
    for (int i = 0; i < 3; ++i) {
        scale += (std::abs(model.gradient[i]) + model.gradient_range[i].magnitude().hi) * half[i];
    }
    // The model is summed in round-to-nearest, and the search compares the field's computed values with it: the
    // slack covers the rounding of both (a few ulps of the terms), as interval.h's bounds are trusted to a few ulps.
    const double slack = 0x1p-40 * scale;
    model.value = {f - slack, f + slack};
    return model;
}

}  // namespace isotrace
