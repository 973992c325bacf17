#pragma once
// A field carried by an affine map: the field of the shape placed by `to_outer`, evaluated in the outer space
// (an instanced scene object, a CSG child that kept its own frame). The value is the inner field's at the mapped
// point, so the sign and zero set are exact; the gradient follows by the chain rule.
#include <memory>

#include "renderer/math/transform.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

std::unique_ptr<ImplicitField> transformed_field(std::unique_ptr<ImplicitField> inner, const Transform& to_outer);

// The axis-aligned box around the image of `box` under the affine `map` (the box of its corners' images: exact,
// the image being the parallelepiped they span), for carrying interval bounds from one frame to another.
IntervalBox transformed_box(const IntervalBox& box, const Transform& map);

}  // namespace isotrace
