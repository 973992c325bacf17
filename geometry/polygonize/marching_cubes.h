#pragma once
// Marching cubes on a lattice (Lorensen & Cline 1987) with the face-consistent table of cube_cycles.h: one vertex
// per cut lattice edge (the crossing found by root search), each cell's cycles triangulated. For a closed
// surface the mesh is a closed, consistently oriented 2-manifold: every face segment is drawn by the two cells
// that share it, fan diagonals never join two edges of one face (cycles where every fan would get a centre
// vertex), and each vertex's triangles form one ring around its edge.
#include "geometry/mesh/triangle_mesh_data.h"
#include "geometry/polygonize/lattice_samples.h"

namespace isotrace {

// Vertices carry unit normals along the field's gradient.
TriangleMeshData marching_cubes(const LatticeSamples& samples, const Lattice& lattice, const ImplicitField& field);

}  // namespace isotrace
