#pragma once
// Smooth vertex normals from the triangles of a mesh.
#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

// Replaces the mesh's normals by the area-weighted average of the normals of the triangles around each vertex
// (after a deformation the old normals are stale). Vertices in no triangle get a zero normal.
void compute_vertex_normals(TriangleMeshData& mesh);

}  // namespace isotrace
