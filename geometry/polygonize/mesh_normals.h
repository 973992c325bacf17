#pragma once
// Shading normals for a polygonised surface: the field's gradient at each vertex, normalised (any unit vector
// where the gradient vanishes). Computed in parallel, in vertex order.
#include <vector>

#include "renderer/math/vec3.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

std::vector<Vec3f> field_normals(const ImplicitField& field, const std::vector<Vec3f>& positions);

}  // namespace isotrace
