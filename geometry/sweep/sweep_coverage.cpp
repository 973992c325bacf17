#include "geometry/sweep/sweep_coverage.h"

#include <algorithm>
#include <cstdio>

namespace isotrace {

SweepCoverage sweep_coverage(const VertexNeighbours& next, const std::vector<std::optional<VertexBinding>>& bindings,
                             const std::vector<double>& weights) {
    SweepCoverage coverage;
    for (std::size_t v = 0; v < next.size(); ++v) {
        if (weights[v] < SweepCoverage::kMovedWeight) continue;
        for (const std::uint32_t w : next[v]) {
            if (weights[w] > 0) continue;
            const std::optional<VertexBinding>& b = bindings[w];
            if (!b) {
                ++coverage.end_plane_edges;
            } else if (b->d > 0) {
                ++coverage.outside_edges;
                if (b->radius > 0) coverage.largest_outside_u = std::max(coverage.largest_outside_u, 1 + b->d / b->radius);
            }
        }
    }
    return coverage;
}

std::string describe(const SweepCoverage& c, double radius_scale) {
    std::string text;
    char part[240];
    if (c.outside_edges > 0) {
        // 10 % beyond the farthest vertex, so that it lies inside rather than on the surface.
        std::snprintf(part, sizeof(part),
                      "%zu edges leave the sweep through its surface from moved vertices (out to %.2f × its radius: "
                      "measured_radius_scale %.3g would enclose them)",
                      c.outside_edges, c.largest_outside_u, radius_scale * c.largest_outside_u * 1.1);
        text = part;
    }
    if (c.end_plane_edges > 0) {
        std::snprintf(part, sizeof(part), "%zu edges from moved vertices cross its end planes", c.end_plane_edges);
        text += (text.empty() ? "" : ", ") + std::string(part);
    }
    return text;
}

}  // namespace isotrace
