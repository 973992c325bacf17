#pragma once
// Which shapes are implicit surfaces, and their fields: each primitive's folder registers a factory under its
// Shape::type_name() (ISOTRACE_REGISTER_IMPLICIT_FIELD), so the polygonisers and commands never name a shape.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geometry/polygonize/implicit_field.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

// The factory may throw std::invalid_argument when this particular shape has no field (an open mesh, say).
// The field may refer to the shape: keep the shape alive while the field is used.
using ImplicitFieldFactory = std::function<std::unique_ptr<ImplicitField>(const Shape&)>;

void register_implicit_field(const std::string& shape_type, ImplicitFieldFactory factory);

// The field of `shape` (in the shape's own space), or null when its type has none.
std::unique_ptr<ImplicitField> implicit_field_of(const Shape& shape);

// The shape types that have a field, sorted (for error messages).
std::vector<std::string> implicit_shape_types();

}  // namespace isotrace

#define ISOTRACE_IMPLICIT_FIELD_CONCAT_INNER(a, b) a##b
#define ISOTRACE_IMPLICIT_FIELD_CONCAT(a, b) ISOTRACE_IMPLICIT_FIELD_CONCAT_INNER(a, b)

// Registers `factory` for shapes whose type_name() is `type`, at library load time.
#define ISOTRACE_REGISTER_IMPLICIT_FIELD(type, ...)                                               \
    namespace {                                                                                   \
    const bool ISOTRACE_IMPLICIT_FIELD_CONCAT(isotrace_implicit_field_, __LINE__) =               \
        (::isotrace::register_implicit_field(type, __VA_ARGS__), true);                           \
    }
