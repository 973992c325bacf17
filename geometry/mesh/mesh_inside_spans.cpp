#include "geometry/mesh/mesh_inside_spans.h"

#include <algorithm>
#include <tuple>

namespace isotrace {
namespace {

BoundaryPoint boundary_point(const MeshCrossing& crossing, double tolerance) {
    return {crossing.t, normalize(crossing.normal), crossing.triangle, 0, tolerance};
}

}  // namespace

void mesh_inside_spans(std::vector<MeshCrossing>& crossings, const Vec3d& direction, double tolerance,
                       std::vector<InsideSpan>& spans) {
    std::sort(crossings.begin(), crossings.end(), [](const MeshCrossing& a, const MeshCrossing& b) {
        return std::tie(a.t, a.triangle) < std::tie(b.t, b.triangle);
    });
    bool inside = false;
    BoundaryPoint enter;
    for (std::size_t first = 0; first < crossings.size();) {
        const double group_end = crossings[first].t + tolerance;
        int net_entries = 0;
        const MeshCrossing *entering = nullptr, *leaving = nullptr;
        std::size_t end = first;
        for (; end < crossings.size() && crossings[end].t <= group_end; ++end) {
            const double facing = dot(crossings[end].normal, direction);
            if (facing < 0) {
                ++net_entries;
                if (!entering) entering = &crossings[end];
            } else if (facing > 0) {
                --net_entries;
                if (!leaving) leaving = &crossings[end];
            }
        }
        if (!inside && net_entries > 0) {
            enter = boundary_point(*entering, tolerance);
            inside = true;
        } else if (inside && net_entries < 0) {
            spans.push_back({enter, boundary_point(*leaving, tolerance)});
            inside = false;
        }
        first = end;
    }
    // Still inside after the last crossing can only be rounding (the line ends outside): that span is dropped.
}

}  // namespace isotrace
