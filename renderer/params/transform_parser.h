#pragma once
#include "renderer/math/transform.h"
#include "renderer/params/scene_node.h"

namespace isotrace {

// Reads a "transform" value. Accepted forms (see docs/scene-format.md):
//   {"matrix": [16 numbers, row-major]}
//   {"translate": [x,y,z], "rotate": ..., "scale": s | [sx,sy,sz]}   applied as translate * rotate * scale
//   [step, step, ...]  each step one of the objects above, applied first to last
// "rotate" is {"axis": [x,y,z], "angle": degrees} or [rx, ry, rz] degrees (about x, then y, then z).
Transform parse_transform(const SceneNode& value);

// A "rotate" value alone: {"axis": [x, y, z], "angle": degrees} or [rx, ry, rz].
Transform parse_rotation(const SceneNode& rotate);

// parse_transform(node["key"]) or identity when absent.
Transform parse_optional_transform(const SceneNode& parent, const std::string& key);

}  // namespace isotrace
