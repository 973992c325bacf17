#include "geometry/polygonize/marching_cubes.h"

#include "geometry/polygonize/cube_cycles.h"
#include "geometry/polygonize/mesh_normals.h"

namespace isotrace {

TriangleMeshData marching_cubes(const LatticeSamples& samples, const Lattice& lattice, const ImplicitField& field) {
    TriangleMeshData mesh;
    for (const Vec3d& p : samples.crossings) mesh.positions.push_back(Vec3f(p));
    std::vector<Vec3d> centres;
    std::uint32_t vertex[12];
    for (std::size_t i = 0; i < samples.cells.size(); ++i) {
        const LatticeIndex cell = lattice_index(samples.cells[i]);
        const CubeCycles& cycles = cube_cycles(samples.inside[i]);
        for (int k = 0; k < cycles.count; ++k) {
            const CubeCycle& cycle = cycles.cycles[k];
            for (int j = 0; j < cycle.length; ++j) {
                const int e = cycle.edges[j];
                const auto ends = cube_edge_corners(e);
                LatticeIndex corner = {cell[0] + (ends[0] & 1), cell[1] + ((ends[0] >> 1) & 1),
                                       cell[2] + ((ends[0] >> 2) & 1)};
                lattice.canonical_edge(corner, e / 4);
                vertex[j] = std::uint32_t(*samples.edge(edge_key(corner, e / 4)));
            }
            if (cycle.needs_centre) {
                Vec3d centre;
                for (int j = 0; j < cycle.length; ++j) centre += Vec3d(mesh.positions[vertex[j]]);
                centre = centre / double(cycle.length);
                const auto c = std::uint32_t(mesh.positions.size());
                mesh.positions.push_back(Vec3f(centre));
                for (int j = 0; j < cycle.length; ++j)
                    mesh.triangles.push_back({c, vertex[j], vertex[(j + 1) % cycle.length]});
            } else {
                const int n = cycle.length;
                for (int j = 1; j + 1 < n; ++j)
                    mesh.triangles.push_back({vertex[cycle.apex], vertex[(cycle.apex + j) % n],
                                              vertex[(cycle.apex + j + 1) % n]});
            }
        }
    }
    mesh.normals = field_normals(field, mesh.positions);
    return mesh;
}

}  // namespace isotrace
