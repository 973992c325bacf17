#pragma once
// The stretch of a line o + t·d inside an axis-aligned box (the slab method): the one line–box clip of isotrace,
// used by bounding boxes, the box primitive, superquadrics, mesh span queries and blob cells. The box is closed:
// a line running along a face, or touching an edge, meets it in a segment or a point.
#include <bit>
#include <limits>
#include <optional>

#include "renderer/math/branch_free.h"
#include "renderer/math/double4.h"
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
    // The three slabs side by side in lanes, and [t_min, t_max] as a fourth (o = 0, d = 1): two divisions of four
    // lanes instead of six of one (a blob ray clips a cell per query), each lane's value as the scalar slab method
    // would compute it, so the same bits. Which slab ends the stretch is data: masks, not branches.
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const Double4 o{origin.x, origin.y, origin.z, 0.0}, d{direction.x, direction.y, direction.z, 1.0};
    const Double4 low{lower.x, lower.y, lower.z, t_min}, high{upper.x, upper.y, upper.z, t_max};
    const Mask4 parallel = d == 0.0;
    if (mask_bits(parallel & ((o < low) | (o > high))) != 0) return std::nullopt;
    const Double4 a = (low - o) / d, b = (high - o) / d;
    // A slab parallel to the line does not limit it; nor does one whose distance is not a number (scalar max and
    // min with NaN keep the other operand).
    const Double4 near = select(parallel | (a != a), Double4{} - kInfinity, select(b < a, b, a));
    const Double4 far = select(parallel | (b != b), Double4{} + kInfinity, select(b < a, a, b));
    // Axis by axis from the clip range, as the scalar method runs (the same zero's sign where ends tie).
    LineBoxClip clip{near[3], far[3]};
    for (int axis = 0; axis < 3; ++axis) {
        clip.t_enter = max_branch_free(near[axis], clip.t_enter);
        clip.t_exit = min_branch_free(far[axis], clip.t_exit);
    }
    if (!(clip.t_enter <= clip.t_exit)) return std::nullopt;
    // The first axis whose slab sets each end (none when the clip range does).
    const Mask4 axes{-1, -1, -1, 0};
    const unsigned enters = mask_bits(axes & (near == clip.t_enter) & (near > t_min));
    const unsigned exits = mask_bits(axes & (far == clip.t_exit) & (far < t_max));
    clip.enter_axis = enters != 0 ? std::countr_zero(enters) : -1;
    clip.exit_axis = exits != 0 ? std::countr_zero(exits) : -1;
    return clip;
}

}  // namespace isotrace
