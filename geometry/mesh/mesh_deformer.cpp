#include "geometry/mesh/mesh_deformer.h"

#include <algorithm>
#include <cstdio>

#include "geometry/mesh/vertex_normals.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {

Registry<MeshDeformer>& mesh_deformer_registry() {
    static Registry<MeshDeformer> registry("deformer");
    return registry;
}

namespace {

std::unique_ptr<MeshDeformer> create_deformer(const SceneNode& element) {
    if (!element.json().is_object()) element.fail("expected a deformer object");
    return mesh_deformer_registry().create(element);
}

std::shared_ptr<const SceneFileContext> file_context(const std::string& path, std::shared_ptr<MemoryBudget> memory) {
    auto context = std::make_shared<SceneFileContext>();
    context->file = path;
    context->directory = std::filesystem::path(path).parent_path();
    context->memory = std::move(memory);
    return context;
}

std::vector<std::string> apply_list(const SceneNode& list, TriangleMeshData& mesh) {
    const MemoryReservation working_memory = check_mesh_deformers(list, mesh);
    const std::vector<SceneNode> elements = list.elements();
    std::vector<std::string> summaries;
    for (const SceneNode& element : elements) {
        summaries.push_back(create_deformer(element)->apply(mesh));
        // An extreme edit can throw vertices beyond float range: report it here, not as a broken render.
        for (const Vec3f& p : mesh.positions)
            if (!is_finite(p)) element.fail("the deformation moved a vertex to a non-finite position");
    }
    compute_vertex_normals(mesh);
    return summaries;
}

}  // namespace

MemoryReservation check_mesh_deformers(const SceneNode& list, const TriangleMeshData& mesh) {
    if (!list.json().is_array()) list.fail("expected a list of deformers or the name of a deformer file");
    const std::vector<SceneNode> elements = list.elements();
    std::uint64_t steps = 0, peak_bytes = 0;
    for (const SceneNode& element : elements) {
        const MeshDeformer::Cost cost = create_deformer(element)->cost(mesh);
        steps = saturating_sum({steps, cost.steps});
        peak_bytes = std::max(peak_bytes, cost.peak_bytes);
    }
    const std::size_t vertices = mesh.positions.size();
    if (steps > kMaxDeformerSteps) {
        char figures[96];
        std::snprintf(figures, sizeof figures, "%.3g steps, more than the limit of %.3g", double(steps),
                      double(kMaxDeformerSteps));
        list.fail(std::to_string(elements.size()) + " deformer" + (elements.size() == 1 ? "" : "s") + " on " +
                  std::to_string(vertices) + " vertices need about " + figures +
                  " (a step: one sweep sample for one vertex, or one operation of a sweep's solve)");
    }
    return MemoryReservation(*list.context().memory, peak_bytes, "deforming " + std::to_string(vertices) + " vertices",
                             list.location(), list.path());
}

DeformerFile::DeformerFile(const std::string& path, std::shared_ptr<MemoryBudget> memory)
    : document_(parse_json_file(path, kDefaultMaxJsonFileBytes, memory.get())),
      root_(document_, "", file_context(path, std::move(memory))) {
    if (!document_.is_object()) root_.fail("expected an object {\"deformers\": [...]}");
    list_ = root_.optional_value("deformers");
    if (!list_) root_.fail("missing \"deformers\"");
}

std::vector<std::string> apply_mesh_deformer_file(const std::string& path, TriangleMeshData& mesh,
                                                  std::shared_ptr<MemoryBudget> memory) {
    const DeformerFile file(path, std::move(memory));
    std::vector<std::string> summaries = apply_list(file.list(), mesh);
    file.finish();
    return summaries;
}

std::vector<std::string> apply_mesh_deformers(const SceneNode& node, TriangleMeshData& mesh) {
    const std::optional<SceneNode> deformers = node.optional_value("deformers");
    if (!deformers) return {};
    if (deformers->json().is_string())
        return apply_mesh_deformer_file(node.file_path("deformers").string(), mesh, node.context().memory);
    return apply_list(*deformers, mesh);
}

}  // namespace isotrace
