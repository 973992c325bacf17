#pragma once
// How well a deformed mesh kept the shape of its input (same vertices and triangles, moved): faces turned over
// against the input's orientation, the largest factor by which an edge grew, and edges that pass through a
// triangle they do not touch (self-intersections), counted in the output and, for comparison, in the input.
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

struct MeshQuality {
    std::size_t flipped_faces = 0;         // output normal against the input normal (dot < 0)
    double max_edge_stretch = 1;           // max over edges of output length / input length
    std::size_t stretched_edges = 0;       // edges longer than kStretchLimit × their input length
    std::size_t crossing_edges = 0;        // output edges through a triangle not sharing an end point
    std::size_t input_crossing_edges = 0;  // the same count on the input (a mesh may intersect itself already)

    static constexpr double kStretchLimit = 2;
};

// Peak working memory per triangle while measuring: the edge list (three pairs before duplicates go) and a traced
// copy of the mesh with Embree's BVH (about 200 bytes per triangle, as measured for sweep tubes).
inline constexpr std::uint64_t kMeshQualityBytesPerTriangle = 3 * 2 * sizeof(std::uint32_t) + 200;

// `before` and `after` have the same triangles; throws std::invalid_argument otherwise.
MeshQuality measure_mesh_quality(const TriangleMeshData& before, const TriangleMeshData& after);

// "0 flipped faces, max edge stretch 1.31× (0 edges > 2×), 0 self-intersecting edges (input 12)".
std::string describe(const MeshQuality& quality);

}  // namespace isotrace
