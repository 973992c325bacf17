#include "geometry/field/surface_bounds.h"

#include <cmath>
#include <cstdint>
#include <queue>
#include <vector>

#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

// A bound on the cells popped by one face's search, far above what a surface needs (a face of the search is
// found after some tens of cells per level); when reached, the farthest queued cell still gives a correct face.
constexpr std::size_t kMaxPops = std::size_t(1) << 20;

struct Cell {
    double reach;     // how far the cell extends along the face's direction
    int level;
    FieldBox box;
};

// The cell reaching farther comes first; between equal reaches, the finer one (so that a flat face ends the
// search at its first finest cell instead of splitting the whole face level by level).
struct Farther {
    bool operator()(const Cell& a, const Cell& b) const {
        return a.reach != b.reach ? a.reach < b.reach : a.level < b.level;
    }
};

// How far the surface reaches along +axis (sign 1) or −axis (sign −1), as a coordinate times sign.
double farthest(const ImplicitField& field, const FieldBox& root, int axis, double sign) {
    const auto reach = [&](const FieldBox& box) { return sign > 0 ? box.upper[axis] : -box.lower[axis]; };
    std::priority_queue<Cell, std::vector<Cell>, Farther> queue;
    queue.push({reach(root), 0, root});
    for (std::size_t pops = 0; !queue.empty(); ++pops) {
        const Cell cell = queue.top();
        if (pops == kMaxPops) return cell.reach;
        queue.pop();
        const Vec3d centre = cell.box.centre();
        if (!field.may_reach_surface(centre, 0.5 * length(cell.box.extent()))) continue;
        // f of one sign all over the cell, grown by a hair: no surface in it, not even on its faces (a hard
        // cube's face on the face of a cell inside it has f < 0 all over that closed cell).
        const Vec3d hair = cell.box.extent() * 1e-6;
        const Interval range = field.value_range({{cell.box.lower.x - hair.x, cell.box.upper.x + hair.x},
                                                  {cell.box.lower.y - hair.y, cell.box.upper.y + hair.y},
                                                  {cell.box.lower.z - hair.z, cell.box.upper.z + hair.z}});
        if (range.lo > 0 || range.hi < 0) continue;
        if (cell.level == kSurfaceBoundsDepth) return cell.reach;
        for (int child = 0; child < 8; ++child) {
            FieldBox box = cell.box;
            for (int a = 0; a < 3; ++a) ((child >> a) & 1 ? box.lower[a] : box.upper[a]) = centre[a];
            queue.push({reach(box), cell.level + 1, box});
        }
    }
    return -INFINITY;  // no surface at all
}

}  // namespace

FieldBox surface_bounds(const ImplicitField& field) {
    const FieldBox given = field.bounds();
    if (!is_finite(given.lower) || !is_finite(given.upper) || !(max_component(given.extent()) > 0)) return given;
    // A margin of one finest cell, so that a surface on the given box's faces lies inside cells, not on their faces.
    const Vec3d margin = given.extent() / double(1 << kSurfaceBoundsDepth);
    const FieldBox root{given.lower - margin, given.upper + margin};
    double faces[6];
    parallel_for(0, 6, [&](int face) { faces[face] = farthest(field, root, face / 2, face % 2 ? 1.0 : -1.0); });
    FieldBox box;
    for (int axis = 0; axis < 3; ++axis) {
        box.lower[axis] = -faces[2 * axis];
        box.upper[axis] = faces[2 * axis + 1];
    }
    if (!(box.lower.x <= box.upper.x && box.lower.y <= box.upper.y && box.lower.z <= box.upper.z)) return given;
    return {max(box.lower, root.lower), min(box.upper, root.upper)};
}

}  // namespace isotrace
