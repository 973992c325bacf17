#pragma once
// Whether a triangle mesh encloses a volume, as CSG needs: every edge shared by exactly two triangles that run
// along it in opposite directions (a closed, consistently oriented surface) whose fronts face outwards.
#include <string>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

// Empty when the mesh is closed and faces outwards; otherwise what is wrong, phrased to follow "the mesh",
// with a count and an example edge by vertex indices ("has 6 boundary edges (e.g. 3–7)"). Vertices are compared
// by position, so files that repeat a vertex (at uv or normal seams) still count as closed.
std::string closed_mesh_problem(const TriangleMeshData& mesh);

}  // namespace isotrace
