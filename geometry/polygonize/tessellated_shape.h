#pragma once
// The scene option "tessellate": {"method": "mc"|"dc"|"sdc", "depth": N, "origin": [x, y, z], "pole_cap": ...} on
// an object with an implicit shape replaces the shape by its polygonisation, traced by Embree as triangles, so a
// scene can show the tessellated surface beside the exact one.
#include <memory>

#include "renderer/plugin/shape.h"
#include "renderer/params/scene_node.h"

namespace isotrace {

// Reads the settings from `settings` (the "tessellate" object); errors are reported there (a shape without a
// field, a bad depth or origin, a surface with nothing to mesh).
std::unique_ptr<Shape> tessellated_shape(std::unique_ptr<Shape> shape, const SceneNode& settings);

}  // namespace isotrace
