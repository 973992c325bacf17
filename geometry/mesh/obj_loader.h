#pragma once
// Wavefront OBJ meshes, parsed by tinyobjloader. All groups and objects become one mesh; materials are ignored.
#include <string>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

// Polygons are fan-triangulated (they must be convex). Each distinct (position, normal, uv) corner becomes
// one vertex, so per-corner attributes survive exactly; normals or uvs are kept only if every corner has one.
// Throws InputError naming `path` (and the line when the parser knows it).
TriangleMeshData load_obj(const std::string& path);

}  // namespace isotrace
