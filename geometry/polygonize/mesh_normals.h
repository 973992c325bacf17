#pragma once
// Shading normals for a polygonised surface: the field's gradient at each vertex, normalised (any unit vector
// where the gradient vanishes). Computed in parallel, in vertex order.
#include <vector>

#include "geometry/polygonize/implicit_field.h"
#include "renderer/math/vec3.h"

namespace isotrace {

std::vector<Vec3f> field_normals(const ImplicitField& field, const std::vector<Vec3f>& positions);

}  // namespace isotrace
