#pragma once
// How far a polygonised mesh lies from the field's true surface.
// - At the vertices: |f|/|∇f|, the first-order distance (exact for signed-distance fields).
// - Two-sided Hausdorff estimate by sampling: mesh → surface over points drawn uniformly by area on the triangles
//   (|f|/|∇f| at each); surface → mesh over surface points found as sign changes along lines through the bounds
//   (bisected to the root), each measured to the nearest triangle. Both are maxima over the samples, so they
//   estimate the true distances from below.
#include <cstddef>
#include <cstdint>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

struct MeshError {
    double vertex_mean = 0, vertex_max = 0;
    double mesh_to_surface = 0, surface_to_mesh = 0;
    std::size_t surface_samples = 0;  // surface points found for the second direction

    double hausdorff() const { return mesh_to_surface > surface_to_mesh ? mesh_to_surface : surface_to_mesh; }
};

// `samples` points on the mesh and about as many surface points; deterministic for a given seed.
MeshError measure_mesh_error(const ImplicitField& field, const TriangleMeshData& mesh, std::size_t samples,
                             std::uint64_t seed = 1);

}  // namespace isotrace
