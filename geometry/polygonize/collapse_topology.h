#pragma once
// The topology test of octree simplification (dual contouring, Ju et al. 2002 §4.2, made strict enough for the
// manifold variant): may the eight children of an octree node, each a leaf with at most one surface component,
// be replaced by one leaf with one vertex?
//
// The test reads the signs at the 3 × 3 × 3 corners of the children (bit x + 3y + 9z set: inside). Each child's
// surface is, by induction, a disc whose boundary crosses each of the child's faces in at most one arc and each of
// its edges at most once, so the surface inside the node is the marching-cubes surface of this 2 × 2 × 2 grid up to
// homeomorphism. The collapse is allowed when
//   - every child's sign pattern has at most one cycle (one disc, cube_cycles.h);
//   - no face of the grid (36) is ambiguous (four sign changes round it): each holds at most one arc;
//   - each of the node's 12 edges changes sign at most once along its three points;
//   - each of the node's 6 faces changes sign at most twice round its 8 boundary points, and has its centre on
//     the boundary's side when it does not change (no closed loop in the face): one arc per node face;
//   - the surface in the node is connected and has Euler characteristic V − E + F = 1 (cut grid edges − cut grid
//     faces + children with surface): a disc;
//   - the node's own 8-corner pattern has exactly one cycle, which is then that disc's boundary.
// Then the node's disc meets each neighbouring leaf's in at most one arc and the dual mesh stays a closed
// 2-manifold (docs/polygonize.md).
#include <cstdint>

namespace isotrace {

// The 27 signs as bits: point (x, y, z), each coordinate 0..2, is bit x + 3y + 9z.
bool collapse_keeps_topology(std::uint32_t inside);

}  // namespace isotrace
