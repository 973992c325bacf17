#pragma once
// The field sampled on a lattice where the surface is: the octree descent keeps the bricks (nodes 8 finest cells
// wide) that may hold surface, the field is sampled at every corner of their cells, and the cells whose corners
// differ in sign are the surface cells — with the signs at their corners and the Hermite data (crossing point and
// gradient) on every edge whose ends differ in sign. Marching cubes and dual contouring both start from here.
// Only the surface cells, their corners and their edges are kept: memory follows the surface, not the lattice.
//
// A cell whose corners differ in sign holds surface, so it is one the descent to the finest level would have kept
// (may_reach_surface is conservative): the surface cells are those of that descent.
//
// Everything is stored in sorted key order and computed into per-index slots, so the result is the same for any
// thread count.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/polygonize/lattice.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

struct LatticeSamples {
    std::vector<LatticeKey> cells;           // sorted: finest cells with corners of both signs
    std::vector<std::uint8_t> inside;        // per cell: bit c set when corner c is inside (field < 0)
    std::vector<LatticeKey> edges;           // sorted edge keys (lattice.h) of the edges the surface cuts
    std::vector<Vec3d> crossings;            // per edge: the surface point on it
    std::vector<Vec3d> gradients;            // per edge: the field's gradient there
    std::vector<std::uint8_t> lower_inside;  // per edge: its lower corner is the inside one
    std::vector<LatticeKey> corners;         // sorted canonical keys of the surface cells' corners
    std::vector<std::uint8_t> corner_inside; // per corner: the field is negative there
    std::size_t candidate_cells = 0;         // finest cells of the bricks the descent kept
    std::size_t corner_samples = 0;          // field values taken at their corners

    std::optional<std::size_t> cell(LatticeKey key) const;
    std::optional<std::size_t> edge(LatticeKey key) const;
    std::optional<std::size_t> corner(LatticeKey key) const;
};

LatticeSamples sample_lattice(const ImplicitField& field, const Lattice& lattice);

// The point on the lattice edge from `corner` along `axis` where the field changes sign, given the values at its
// ends (one < 0, the other ≥ 0): regula falsi (Illinois) safeguarded by bisection, in the lattice's coordinates
// (on a spherical lattice an edge in θ or φ is an arc).
Vec3d edge_crossing(const ImplicitField& field, const Lattice& lattice, const LatticeIndex& corner, int axis,
                    double lower_value, double upper_value);

}  // namespace isotrace
