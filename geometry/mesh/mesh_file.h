#pragma once
// Entry point for mesh files: picks the loader from the file extension.
#include <string>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

// .obj or .ply (any letter case). Throws InputError naming `path` for an unsupported extension or any
// problem the loader finds. The result is validated; degenerate triangles are kept.
TriangleMeshData load_mesh_file(const std::string& path);

}  // namespace isotrace
