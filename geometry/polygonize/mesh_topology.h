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

// Undirected edges used by one triangle (a hole's rim) and by more than two (non-manifold).
struct EdgeUse {
    std::size_t boundary = 0, over_shared = 0;
};
EdgeUse edge_use(const TriangleMeshData& mesh);

// V − E + F over the vertices the triangles use: 2 for a sphere, 0 for a torus (per closed component).
long euler_characteristic(const TriangleMeshData& mesh);

// Closed and consistently oriented, and around every vertex its triangles form one ring (no pinched vertices).
bool is_closed_two_manifold(const TriangleMeshData& mesh);

}  // namespace isotrace
