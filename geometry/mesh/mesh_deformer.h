#pragma once
// Deformers change a triangle mesh's vertices as it loads (the "deformers" list of a mesh shape) or offline
// (`isotrace deform`). They are plugins: each family registers its types here from its own folder (the sweep
// deformers of geometry/sweep), so the mesh layer never names one.
#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/plugin/registry.h"

namespace isotrace {

class MeshDeformer {
public:
    virtual ~MeshDeformer() = default;
    // Moves the vertices in place (triangles untouched). Returns one line of statistics for the user.
    // Problems with the deformer's own input throw InputError naming its place in the file.
    virtual std::string apply(TriangleMeshData& mesh) const = 0;
};

Registry<MeshDeformer>& mesh_deformer_registry();

// Applies node["deformers"] when present: a list of deformer objects, or the name of a JSON file (relative to
// the scene) holding {"deformers": [...]}. Deformers run in order; afterwards vertex normals are recomputed
// (the old ones no longer fit). Returns each deformer's statistics line.
std::vector<std::string> apply_mesh_deformers(const SceneNode& node, TriangleMeshData& mesh);

// The deformers of a file holding {"deformers": [...]} (for `isotrace deform` and file references).
std::vector<std::string> apply_mesh_deformer_file(const std::string& path, TriangleMeshData& mesh);

}  // namespace isotrace
