#include "geometry/abm_patch/boundary_tubes.h"

#include <stdexcept>

#include "geometry/mesh/vertex_normals.h"
#include "geometry/sweep/sweep_surface.h"

namespace isotrace {
namespace {

constexpr int kKeySections = 33;
constexpr int kRadiusSamples = 8;

SweepSurface tube_along(const SpaceCurve& curve, double radius) {
    std::vector<Vec3d> centres;
    for (int k = 0; k < kKeySections; ++k) centres.push_back(curve(double(k) / (kKeySections - 1)));
    std::vector<KeySection> keys;
    Vec3d side{}, unused{};
    for (int k = 0; k < kKeySections; ++k) {
        // The chord through the neighbours: defined even where the curve's derivative vanishes.
        const Vec3d along = normalize(centres[std::size_t(std::min(k + 1, kKeySections - 1))] -
                                      centres[std::size_t(std::max(k - 1, 0))]);
        if (k == 0) orthonormal_basis(along, side, unused);
        side = normalize(side - dot(side, along) * along);  // parallel transport: no twist about the curve
        keys.push_back({centres[std::size_t(k)], Quaternion::from_axes(side, cross(along, side), along),
                        std::vector<double>(kRadiusSamples, radius)});
    }
    return SweepSurface(std::move(keys));
}

}  // namespace

TriangleMeshData boundary_tubes(const std::vector<const SpaceCurve*>& curves, double radius) {
    if (!(radius > 0)) throw std::invalid_argument("tube_radius: must be > 0");
    TriangleMeshData tubes;
    for (const SpaceCurve* curve : curves) {
        tubes.append_positions_and_triangles(tessellate(tube_along(*curve, radius), kBoundaryTube));
    }
    tubes.remove_degenerate_triangles();
    compute_vertex_normals(tubes);
    unwrap_tube_seams(tubes);
    return tubes;
}

}  // namespace isotrace
