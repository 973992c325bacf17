#pragma once
// Tessellates the surface of a blob group (Σ wᵢ·fᵢ = T) into a closed, consistently oriented triangle mesh:
// for tracing the same surface natively as triangles (the direct-vs-tessellated benchmark) and as a user
// feature (export, comparison with other renderers).
//
// Sparse marching tetrahedra: only lattice bricks that overlap some element's support are sampled (elsewhere the
// field is 0 < T), each cell is cut by the Kuhn split (see marching_tetrahedra.h), vertices are shared between
// cells through their lattice-edge key, placed on the surface by a bracketed root search along the edge and
// given the normal −∇F. Output is identical for any thread count: bricks are processed independently and
// merged in key order, vertices are numbered by sorted edge key.
#include "geometry/implicit/blob_group.h"
#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

struct PolygonizeSettings {
    double cell_size = 0;  // lattice spacing in world units, > 0
};

// The cell size that puts `cells_per_radius` cells across the smallest element's support half-width (the field
// radius R of a metaball). Throws std::invalid_argument for cells_per_radius that is not finite and > 0.
double cell_size_for_smallest_element(const BlobGroup& group, double cells_per_radius);

// Throws std::invalid_argument ("cell_size: ...") for a cell size that is not finite and > 0, that needs more
// than 2^20 lattice cells along an axis, or that would sample more than 2^26 bricks of 8³ cells. The mesh has no triangles when the field never exceeds the threshold.
TriangleMeshData polygonize(const BlobGroup& group, const PolygonizeSettings& settings);

}  // namespace isotrace
