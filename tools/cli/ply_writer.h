#pragma once
// Writes one triangle mesh as a binary little-endian PLY file (positions, normals when present, triangles), which
// isotrace's own PLY reader and common tools read.
#include <string>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace::cli {

// Atomically (see renderer/core/atomic_file.h); throws std::runtime_error when the file cannot be written.
void write_ply(const std::string& path, const TriangleMeshData& mesh);

}  // namespace isotrace::cli
