#include "geometry/csg/material_reference_parser.h"

namespace isotrace {

MaterialReference material_reference(const SceneNode& value) {
    if (!value.json().is_string()) value.fail("expected the name of a material from \"materials\"");
    return {value.json().string, value.location(), value.path()};
}

MaterialReference optional_material_reference(const SceneNode& node) {
    const auto value = node.optional_value("material");
    return value ? material_reference(*value) : MaterialReference{};
}

}  // namespace isotrace
