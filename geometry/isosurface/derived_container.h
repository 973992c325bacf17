#pragma once
// A container proven for a function given without one: the smallest cube [−R, R]³ (R = 2^k metres, k from
// kSmallestDerivedHalfSize to kLargestDerivedHalfSize) such that interval arithmetic proves f > 0 over each of the
// six unbounded slabs outside it (x ≥ R with y and z anything, x ≤ −R, and so on for y and z). Then all of the
// solid {f < 0} lies in the cube, and the cube holds the whole surface. Each face of the cube is then moved inwards
// as far as interval arithmetic proves f > 0 between its old and new place (by bisection), so that a solid off the
// origin gets a box about itself. Functions whose intervals cannot prove it
// (a gyroid fills space; a plane is unbounded; loose bounds can also fail) get nothing: they need a container.
#include <optional>

#include "geometry/isosurface/container.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

constexpr int kSmallestDerivedHalfSize = -16;  // 2⁻¹⁶ m, about 15 µm
constexpr int kLargestDerivedHalfSize = 20;    // 2²⁰ m, about 1000 km

// `field`'s value_range must hold over boxes with infinite ends.
std::optional<Container> derive_container(const ImplicitField& field);

}  // namespace isotrace
