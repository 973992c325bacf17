#pragma once
// The stretch of a line o + t·d inside an axis-aligned box (the slab method): the one line–box clip of isotrace,
// used by bounding boxes, the box primitive, superquadrics, mesh span queries and blob cells. The box is closed:
// a line running along a face, or touching an edge, meets it in a segment or a point.
#include <algorithm>
#include <optional>

#include "renderer/math/branch_free.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct LineBoxClip {
    double t_enter, t_exit;  // t_enter ≤ t_exit
    // The axis whose slab set t_enter / t_exit (−1 when the clip range did): the face the line enters or leaves
    // through is that axis's low or high face, by the sign of d along it.
    int enter_axis = -1, exit_axis = -1;
};

// The part of [t_min, t_max] where o + t·d lies in [lower, upper], or nothing. d may have zero components (the
// line then lies in that slab or misses the box) and need not be unit length.
inline std::optional<LineBoxClip> clip_line_to_box(const Vec3d& lower, const Vec3d& upper, const Vec3d& origin,
                                                   const Vec3d& direction, double t_min, double t_max) {
    LineBoxClip clip{t_min, t_max};
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0) {
            if (origin[axis] < lower[axis] || origin[axis] > upper[axis]) return std::nullopt;
            continue;
        }
        double t_near = (lower[axis] - origin[axis]) / direction[axis];
        double t_far = (upper[axis] - origin[axis]) / direction[axis];
        if (t_near > t_far) std::swap(t_near, t_far);
        // Which slab ends the stretch is data (a blob ray clips a cell per query): selects, not branches.
        const bool enters_later = t_near > clip.t_enter, exits_earlier = t_far < clip.t_exit;
        clip.enter_axis = enters_later ? axis : clip.enter_axis;
        clip.exit_axis = exits_earlier ? axis : clip.exit_axis;
        clip.t_enter = max_branch_free(t_near, clip.t_enter);
        clip.t_exit = min_branch_free(t_far, clip.t_exit);
    }
    if (!(clip.t_enter <= clip.t_exit)) return std::nullopt;
    return clip;
}

}  // namespace isotrace
