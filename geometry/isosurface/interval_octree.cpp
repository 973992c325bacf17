#include "geometry/isosurface/interval_octree.h"

namespace isotrace {
namespace {

// Whether the surface of {f < 0} ∩ container may pass through `cell`.
bool may_hold_surface(const ImplicitField& field, const Container& container, const IntervalBox& cell) {
    const Interval range = field.value_range(cell);
    if (range.lo > 0) return false;  // outside the function's solid
    const Interval distance = container.distance_range(cell);
    if (distance.lo > 0) return false;  // outside the container
    // Not a number (a range that could not be computed) keeps the cell.
    const bool deep_inside = range.hi < 0;
    return !deep_inside || distance.contains(0);
}

void split(const IntervalBox& cell, std::vector<IntervalBox>& out) {
    const Vec3d middle = (cell.lower() + cell.upper()) * 0.5;
    for (int octant = 0; octant < 8; ++octant) {
        IntervalBox child;
        for (int k = 0; k < 3; ++k)
            child[k] = octant & (1 << k) ? Interval{middle[k], cell[k].hi} : Interval{cell[k].lo, middle[k]};
        out.push_back(child);
    }
}

}  // namespace

std::vector<IntervalBox> surface_cells(const ImplicitField& field, const Container& container, const OctreeLimits& limits,
                                       MemoryBudget& memory, const SourceLocation& where) {
    std::vector<IntervalBox> cells;
    if (may_hold_surface(field, container, container.bounds())) cells.push_back(container.bounds());
    for (int depth = 0; depth < limits.max_depth && !cells.empty(); ++depth) {
        // The next level's candidates and the cells kept of them, for as long as the level is built.
        const MemoryReservation level(memory, 2 * cells.size() * 8 * sizeof(IntervalBox), "isosurface octree cells",
                                      where);
        std::vector<IntervalBox> candidates, children;
        for (const IntervalBox& cell : cells) split(cell, candidates);
        for (const IntervalBox& child : candidates)
            if (may_hold_surface(field, container, child)) children.push_back(child);
        // Counted among the cells kept, not the candidates: a surface keeps a quarter to a half of them.
        if (children.size() > limits.max_cells) break;
        cells.swap(children);
    }
    memory.charge(cells.size() * sizeof(IntervalBox), "isosurface octree cells", where);
    return cells;
}

}  // namespace isotrace
