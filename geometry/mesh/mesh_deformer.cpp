#include "geometry/mesh/mesh_deformer.h"

#include "geometry/mesh/vertex_normals.h"
#include "renderer/scene/json_document.h"

namespace isotrace {

Registry<MeshDeformer>& mesh_deformer_registry() {
    static Registry<MeshDeformer> registry("deformer");
    return registry;
}

namespace {

std::vector<std::string> apply_list(const SceneNode& list, TriangleMeshData& mesh) {
    if (!list.json().is_array()) list.fail("expected a list of deformers or the name of a deformer file");
    std::vector<std::string> summaries;
    for (const SceneNode& element : list.elements()) {
        if (!element.json().is_object()) element.fail("expected a deformer object");
        summaries.push_back(mesh_deformer_registry().create(element)->apply(mesh));
        // An extreme edit can throw vertices beyond float range: report it here, not as a broken render.
        for (const Vec3f& p : mesh.positions)
            if (!is_finite(p)) element.fail("the deformation moved a vertex to a non-finite position");
    }
    compute_vertex_normals(mesh);
    return summaries;
}

}  // namespace

std::vector<std::string> apply_mesh_deformer_file(const std::string& path, TriangleMeshData& mesh) {
    const JsonValue document = parse_json_file(path);
    auto context = std::make_shared<SceneFileContext>();
    context->file = path;
    context->directory = std::filesystem::path(path).parent_path();
    const SceneNode root(document, "", context);
    if (!document.is_object()) root.fail("expected an object {\"deformers\": [...]}");
    const std::optional<SceneNode> list = root.optional_value("deformers");
    if (!list) root.fail("missing \"deformers\"");
    std::vector<std::string> summaries = apply_list(*list, mesh);
    root.finish();
    return summaries;
}

std::vector<std::string> apply_mesh_deformers(const SceneNode& node, TriangleMeshData& mesh) {
    const std::optional<SceneNode> deformers = node.optional_value("deformers");
    if (!deformers) return {};
    if (deformers->json().is_string()) return apply_mesh_deformer_file(node.file_path("deformers").string(), mesh);
    return apply_list(*deformers, mesh);
}

}  // namespace isotrace
