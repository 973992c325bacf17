#pragma once
// Deformers change a triangle mesh's vertices as it loads (the "deformers" list of a mesh shape) or offline
// (`isotrace deform`). They are plugins: each family registers its types here from its own folder (the sweep
// deformers of geometry/sweep), so the mesh layer never names one.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/core/memory_budget.h"
#include "renderer/params/json_document.h"
#include "renderer/plugin/registry.h"

namespace isotrace {

class MeshDeformer {
public:
    // What applying the deformer to `mesh` takes, known before any of it is done.
    struct Cost {
        std::uint64_t steps = 0;       // evaluations (sweep samples per vertex, solver operations, ...)
        std::uint64_t peak_bytes = 0;  // memory held at once beyond the mesh
    };

    virtual ~MeshDeformer() = default;
    virtual Cost cost(const TriangleMeshData& mesh) const = 0;
    // Moves the vertices in place (triangles untouched). Returns one line of statistics for the user.
    // Problems with the deformer's own input throw InputError naming its place in the file.
    virtual std::string apply(TriangleMeshData& mesh) const = 0;
};

Registry<MeshDeformer>& mesh_deformer_registry();

// The most steps (MeshDeformer::Cost) a list of deformers may take on its mesh: about two minutes on two cores.
inline constexpr std::uint64_t kMaxDeformerSteps = 20'000'000'000;

// A file holding {"deformers": [...]}, named by a scene or given to `isotrace deform`. Its nodes charge `memory`.
class DeformerFile {
public:
    DeformerFile(const std::string& path, std::shared_ptr<MemoryBudget> memory);
    DeformerFile(const DeformerFile&) = delete;
    DeformerFile& operator=(const DeformerFile&) = delete;

    const SceneNode& list() const { return *list_; }  // the value of "deformers"
    void finish() const { root_.finish(); }          // typo protection for the file's top level

private:
    JsonValue document_;
    SceneNode root_;
    std::optional<SceneNode> list_;
};

// Refuses `list` (an array of deformer objects) before any of them works on `mesh` when their steps together
// exceed kMaxDeformerSteps; reserves the working memory of the costliest one while the caller keeps the result.
// Each is read for its cost and dropped.
[[nodiscard]] MemoryReservation check_mesh_deformers(const SceneNode& list, const TriangleMeshData& mesh);

// Applies node["deformers"] when present: a list of deformer objects, or the name of a JSON file (relative to
// the scene) holding {"deformers": [...]}, checked first (check_mesh_deformers). Deformers then run in order;
// afterwards vertex normals are recomputed (the old ones no longer fit). Returns each deformer's statistics line.
std::vector<std::string> apply_mesh_deformers(const SceneNode& node, TriangleMeshData& mesh);

// The deformers of a file holding {"deformers": [...]} (for `isotrace deform`), as above.
std::vector<std::string> apply_mesh_deformer_file(const std::string& path, TriangleMeshData& mesh,
                                                  std::shared_ptr<MemoryBudget> memory);

}  // namespace isotrace
