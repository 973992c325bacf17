#pragma once
// Writes triangle meshes as one Wavefront OBJ file (positions, normals, triangles; one `o` object per mesh), so
// that tessellated surfaces can be opened by other tools or used in a scene as a "mesh" shape.
#include <string>
#include <utility>
#include <vector>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace::cli {

struct NamedMesh {
    std::string name;
    TriangleMeshData mesh;  // normals: empty or one per position
};

// Atomically (see renderer/core/atomic_file.h); throws std::runtime_error when the file cannot be written.
void write_obj(const std::string& path, const std::vector<NamedMesh>& meshes);

}  // namespace isotrace::cli
