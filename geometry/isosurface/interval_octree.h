#pragma once
// The cells of an isosurface's container that may hold its surface, found by interval arithmetic: the container's
// box is split into octants level by level, and a cell is dropped when the field's interval over it proves that
// no surface lies there (f > 0 throughout: outside; f < 0 throughout and away from the container's boundary:
// deep inside). Each remaining cell becomes one Embree primitive with its own bounds, so a ray through empty
// space costs nothing; a field that cannot bound its range (Interval::unbounded) keeps every cell, which is
// correct and only slower.
#include <cstddef>
#include <vector>

#include "geometry/isosurface/container.h"
#include "renderer/core/memory_budget.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

struct OctreeLimits {
    int max_depth = 6;               // levels of halving below the container's box
    std::size_t max_cells = 1 << 16;  // a level that would keep more cells is not made
};

// The cells, at the deepest level within the limits. Each level's cells are charged to `memory` (as `what` at
// `where`) before they are made.
std::vector<IntervalBox> surface_cells(const ImplicitField& field, const Container& container, const OctreeLimits& limits,
                                       MemoryBudget& memory, const SourceLocation& where = {});

}  // namespace isotrace
