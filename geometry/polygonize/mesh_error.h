#pragma once
// How far a polygonised mesh lies from the field's true surface, by sampling.
// - At the vertices (at most kVertexSamples of them, evenly spread over the numbering), and mesh → surface over points
//   drawn uniformly by area on the triangles: the distance to the
//   nearest crossing of the surface along the line of the gradient at the point (found by the ray tracer's
//   guaranteed crossing search, crossing_search.h, with the field's interval bounds), an upper bound of the
//   distance to the surface that is the distance itself near it. (|f|/|∇f|, the first-order estimate, is no
//   distance for fields that are none: it is infinite where a blob field is flat or a hard cube's step decides.)
// - Surface → mesh over surface points found as sign changes along lines through the bounds (bisected to the
//   root), each measured to the nearest triangle.
// The maxima over the samples estimate the two one-sided Hausdorff distances from below.
#include <cstddef>
#include <cstdint>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

constexpr std::size_t kVertexSamples = 20000;

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
