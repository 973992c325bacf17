#pragma once
// Topology checks of triangle meshes for the polygoniser's tests: closedness, orientation, enclosed volume and
// connected components.
#include <cstddef>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

// True when every directed edge (a → b) of a triangle appears exactly once and its reverse (b → a) exactly once:
// the mesh is closed (every edge shared by two triangles) and consistently oriented.
bool is_closed_and_consistently_oriented(const TriangleMeshData& mesh);

// Σ p0·(p1 × p2) / 6 over the triangles: the enclosed volume, positive when the triangles face outwards.
double signed_volume(const TriangleMeshData& mesh);

// Number of groups of triangles connected through shared vertices.
std::size_t connected_components(const TriangleMeshData& mesh);

}  // namespace isotrace
