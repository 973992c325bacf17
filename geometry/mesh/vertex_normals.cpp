#include "geometry/mesh/vertex_normals.h"

namespace isotrace {

void compute_vertex_normals(TriangleMeshData& mesh) {
    std::vector<Vec3d> sums(mesh.positions.size());
    for (const auto& t : mesh.triangles) {
        const Vec3d p0(mesh.positions[t[0]]), p1(mesh.positions[t[1]]), p2(mesh.positions[t[2]]);
        const Vec3d area_normal = cross(p1 - p0, p2 - p0);  // length = twice the area
        for (std::uint32_t corner : t) sums[corner] += area_normal;
    }
    mesh.normals.resize(mesh.positions.size());
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const double len = length(sums[i]);
        mesh.normals[i] = len > 0 ? Vec3f(sums[i] / len) : Vec3f(0, 0, 0);
    }
}

}  // namespace isotrace
