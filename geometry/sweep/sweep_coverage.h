#pragma once
// Whether a sweep covers the part of a mesh it moves. Where a vertex the sweep moves (weight ≥ kMovedWeight)
// shares an edge with one it does not move at all, the deformation may tear or fold there when the sweep is
// edited: either the other vertex lies outside the sweep's surface (the part sticks out of its sweep: the
// bunny's ear rim outside a sweep that is too thin) or beyond its end planes (the weight drops from full to
// nothing at the plane). Counted here, with how far out the outside vertices lie, to suggest a radius scale.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "geometry/sweep/sweep_assignment.h"

namespace isotrace {

struct SweepCoverage {
    static constexpr double kMovedWeight = 0.05;

    std::size_t outside_edges = 0;    // from a moved vertex to an unmoved one outside the surface (bound, d > 0)
    std::size_t end_plane_edges = 0;  // from a moved vertex to one beyond the end planes (unbound)
    double largest_outside_u = 0;     // the largest (r + d)/r of those outside vertices (0: none)
};

// `bindings` and `weights`: one per vertex of the mesh `next` describes.
SweepCoverage sweep_coverage(const VertexNeighbours& next, const std::vector<std::optional<VertexBinding>>& bindings,
                             const std::vector<double>& weights);

// Empty when nothing is wrong; otherwise, for the deform summary: "12 edges leave the sweep through its surface
// from moved vertices (out to 1.40 × its radius: measured_radius_scale 2.1 would enclose them), 30 edges from
// moved vertices cross its end planes". `radius_scale`: the sweep's measured_radius_scale.
std::string describe(const SweepCoverage& coverage, double radius_scale);

}  // namespace isotrace
