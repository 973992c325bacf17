// The "sweep_tubes" shape: the sweeps of sweep deformers as triangle meshes, for showing them (translucent) over
// the mesh they deform. It reads the same deformer list (inline or a file) as a mesh's "deformers".
#include "geometry/mesh/mesh_file.h"
#include "geometry/mesh/triangle_mesh_shape.h"
#include "geometry/mesh/vertex_normals.h"
#include "geometry/sweep/sweep_family_deformer.h"
#include "geometry/sweep/sweep_tessellation.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {
namespace {

// The list's work is bounded as for a mesh's deformers (more than the tubes need: they bind no vertex), and each
// tube is charged to the scene's budget (`shape`'s) before it is tessellated.
void add_tubes(const SceneNode& shape, const SceneNode& list, const TriangleMeshData& mesh, bool edited,
               const SweepTessellation& steps, TriangleMeshData& tubes) {
    (void)check_mesh_deformers(list, mesh);  // the bound on the list's work; tubes bind no vertex
    const std::uint64_t triangles = steps.triangle_count();
    for (const SceneNode& element : list.elements()) {
        const std::unique_ptr<MeshDeformer> deformer = mesh_deformer_registry().create(element);
        const auto* sweeps = dynamic_cast<const SweepFamilyDeformer*>(deformer.get());
        if (!sweeps) element.fail("not a sweep deformer");
        for (const SweepSurface& sweep : sweeps->sweeps(mesh, edited)) {
            shape.context().memory->charge(saturating_product({triangles, kSweepTubeTrianglePeakBytes}),
                                           "a tube of " + std::to_string(triangles) + " triangles (theta_steps " +
                                               std::to_string(steps.theta_steps) + ", t_steps " +
                                               std::to_string(steps.t_steps) + ")",
                                           shape.location(), shape.path());
            tubes.append_positions_and_triangles(at_node(element, [&] { return tessellate(sweep, steps); }));
        }
    }
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    const TriangleMeshData mesh = node.has("measure_on")
                                      ? load_mesh_file(node.file_path("measure_on").string(), *node.context().memory)
                                      : TriangleMeshData{};
    const bool edited = node.choice_or("state", "after", {"before", "after"}) == "after";
    SweepTessellation steps;
    steps.theta_steps = node.integer_or("theta_steps", 48, NumberRange::between(3, 4096));
    steps.t_steps = node.integer_or("t_steps", 64, NumberRange::between(1, 4096));
    TriangleMeshData tubes;
    const std::optional<SceneNode> list = node.optional_value("deformers");
    if (!list) node.fail("needs \"deformers\" (a list or the name of a deformer file)");
    if (list->json().is_string()) {
        const DeformerFile file(node.file_path("deformers").string(), node.context().memory);
        add_tubes(node, file.list(), mesh, edited, steps, tubes);
    } else {
        add_tubes(node, *list, mesh, edited, steps, tubes);
    }
    for (const Vec3f& p : tubes.positions)
        if (!is_finite(p)) node.fail("a sweep reaches beyond float range");
    tubes.remove_degenerate_triangles();
    compute_vertex_normals(tubes);
    unwrap_tube_seams(tubes);
    return std::make_unique<TriangleMeshShape>(std::move(tubes));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "sweep_tubes",
                         "the sweeps of sweep deformers as tubes: deformers (list or file), measure_on (mesh), state "
                         "(before/after), theta_steps, t_steps",
                         create)

}  // namespace isotrace
