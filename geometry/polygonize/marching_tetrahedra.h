#pragma once
// Marching tetrahedra on a cube lattice: every cube is split into the same six tetrahedra (the Kuhn split
// around the diagonal from corner 0 to corner 7), so two cells sharing a face split it along the same diagonal
// and the surface pieces of neighbouring cells meet edge to edge: no cracks and no ambiguous cases.
//
// Cube corners are numbered by bits: corner c lies at (c & 1, (c >> 1) & 1, (c >> 2) & 1) in cell units. Every
// edge of a Kuhn tetrahedron joins a corner a to a corner b whose bits contain a's, so it runs from the lattice
// point of a in the positive direction b & ~a (one of seven): that pair names the edge across all cells.
#include <array>
#include <cstdint>

namespace isotrace {

// An edge crossed by the surface, as two cube corners (one inside, one outside).
struct CutEdge {
    int inside_corner = 0, outside_corner = 0;
};

// A surface triangle whose vertices lie on three cut edges, ordered counter-clockwise seen from outside.
using CutTriangle = std::array<CutEdge, 3>;

// The six tetrahedra of the Kuhn split, as cube corners.
const std::array<std::array<int, 4>, 6>& kuhn_tetrahedra();

// The surface triangles (0, 1 or 2) in a tetrahedron given which of the cube's corners are inside
// (bit c of inside_corners). Writes them to `triangles` and returns their number.
int cut_tetrahedron(const std::array<int, 4>& tetrahedron, std::uint8_t inside_corners,
                    std::array<CutTriangle, 2>& triangles);

}  // namespace isotrace
