#pragma once
// The field each octree cell of an isosurface searches with: its expression's tape pruned to the cell
// (tape_pruning.h), so that a smooth union of distance fields runs, near one of its parts, that part's
// instructions alone. Cells whose pruning settles the same choices share one field.
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/expression/expression_field.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {

struct CellFields {
    std::vector<std::shared_ptr<const ImplicitField>> fields;
    std::vector<std::uint32_t> of_cell;  // an index into fields per cell (0: the whole field); empty: all 0
};

// At most this many instructions in all the pruned tapes of one isosurface (a cell beyond them keeps the whole
// tape): 8 MB.
constexpr std::size_t kMaxPrunedInstructions = std::size_t(1) << 18;

// The pruned fields of `cells` (each pruned over the cell widened by 10⁻⁹ of its size, so that points rounded
// onto its faces lie within), charged to `memory`.
CellFields pruned_cell_fields(const std::shared_ptr<const ExpressionField>& field, const std::vector<IntervalBox>& cells,
                              MemoryBudget& memory, const SourceLocation& where = {});

}  // namespace isotrace
