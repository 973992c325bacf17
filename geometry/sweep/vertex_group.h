#pragma once
// Explicit vertex groups of a sweep hierarchy: the paper segments a mesh into parts by hand; a member of
// "sweeps" may name the vertices that follow it, by index ("vertices") and/or by a selection box ("select":
// {"min", "max"}, in mesh units). Grouped vertices follow their sweep whatever their depth in the others
// (sweep_assignment.h); groups may not overlap, name missing vertices or select nothing.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/params/scene_node.h"

namespace isotrace {

struct VertexGroupSpec {
    SceneNode node;  // the member of "sweeps"
    std::vector<std::pair<std::uint64_t, SceneNode>> indices;
    std::optional<std::pair<Vec3d, Vec3d>> box;  // min, max
};

// Reads "vertices" and "select" of a member of "sweeps"; nothing when it has neither.
std::optional<VertexGroupSpec> parse_vertex_group(const SceneNode& sweep);

// Puts the group's vertices in sweep `sweep` in `grouped` (one entry per vertex of `mesh`, −1 = no group).
// InputError at the field for an index beyond the mesh, a vertex already in another group (`names`: the sweeps'
// names, to say which) or a box that selects no vertex.
void mark_vertex_group(const VertexGroupSpec& group, const TriangleMeshData& mesh, int sweep,
                       const std::vector<std::string>& names, std::vector<int>& grouped);

}  // namespace isotrace
