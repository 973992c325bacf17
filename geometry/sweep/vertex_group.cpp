#include "geometry/sweep/vertex_group.h"

#include <cmath>

namespace isotrace {

std::optional<VertexGroupSpec> parse_vertex_group(const SceneNode& sweep) {
    if (!sweep.has("vertices") && !sweep.has("select")) return std::nullopt;
    VertexGroupSpec group{sweep, {}, std::nullopt};
    if (const auto vertices = sweep.optional_value("vertices")) {
        for (const SceneNode& element : vertices->elements()) {
            const double index = element.as_number(NumberRange::non_negative());
            if (index != std::floor(index)) element.fail("a vertex index must be a whole number");
            group.indices.emplace_back(std::uint64_t(index), element);
        }
        if (group.indices.empty()) vertices->fail("the list names no vertex");
    }
    if (const auto select = sweep.optional_object("select")) {
        group.box = {{select->vec3("min"), select->vec3("max")}};
        if (!(group.box->first.x <= group.box->second.x && group.box->first.y <= group.box->second.y &&
              group.box->first.z <= group.box->second.z))
            select->fail("\"min\" must not exceed \"max\" on any axis");
        select->finish();
    }
    return group;
}

void mark_vertex_group(const VertexGroupSpec& group, const TriangleMeshData& mesh, int sweep,
                       const std::vector<std::string>& names, std::vector<int>& grouped) {
    auto mark = [&](std::size_t v, const SceneNode& where) {
        if (grouped[v] >= 0 && grouped[v] != sweep)
            where.fail("vertex " + std::to_string(v) + " is also in the group of sweep \"" + names[std::size_t(grouped[v])] + "\"");
        grouped[v] = sweep;
    };
    for (const auto& [index, element] : group.indices) {
        if (index >= mesh.positions.size())
            element.fail("vertex " + std::to_string(index) + " does not exist (the mesh has " +
                         std::to_string(mesh.positions.size()) + " vertices)");
        mark(std::size_t(index), element);
    }
    if (!group.box) return;
    const SceneNode select = group.node.object("select");
    std::size_t selected = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3d p(mesh.positions[v]);
        const auto& [low, high] = *group.box;
        if (p.x < low.x || p.y < low.y || p.z < low.z || p.x > high.x || p.y > high.y || p.z > high.z) continue;
        mark(v, select);
        ++selected;
    }
    if (selected == 0) select.fail("the box selects no vertex of the mesh");
}

}  // namespace isotrace
