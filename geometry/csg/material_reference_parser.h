#pragma once
// Per-part material names in scene files (a CSG child's "material", a blob element's): read as MaterialReference,
// with where they are written, so that the scene loader resolves them and reports an unknown name at its place.
#include "renderer/params/scene_node.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

// The name at `value`, which must be a string.
MaterialReference material_reference(const SceneNode& value);
// The optional "material" key of `node`; no name (the part shows the object's material) when absent.
MaterialReference optional_material_reference(const SceneNode& node);

}  // namespace isotrace
