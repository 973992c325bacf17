#pragma once
// Stanford PLY meshes (ascii, binary_little_endian, binary_big_endian), read by our own parser.
#include <string>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

// Reads the `vertex` element (x, y, z; optional nx, ny, nz and u, v / s, t / texture_u, texture_v) and the
// `face` element (list vertex_indices or vertex_index; polygons are fan-triangulated, so must be convex).
// Other elements and properties are skipped. Throws InputError naming `path`, the line (header, or ASCII
// body) and the record, e.g. "bunny.ply:12: face 3: vertex index 99 out of range (vertex count 8)".
TriangleMeshData load_ply(const std::string& path);

}  // namespace isotrace
