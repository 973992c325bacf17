#include "geometry/isosurface/cell_fields.h"

#include <map>

#include "geometry/expression/expression_tape.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {

CellFields pruned_cell_fields(const std::shared_ptr<const ExpressionField>& field, const std::vector<IntervalBox>& cells,
                              MemoryBudget& memory, const SourceLocation& where) {
    std::vector<std::vector<std::uint8_t>> choices(cells.size());
    parallel_for(std::size_t(0), cells.size(), [&](std::size_t i) {
        IntervalBox box = cells[i];
        for (int k = 0; k < 3; ++k) {
            const double margin = 1e-9 * box[k].width();
            box[k] = {box[k].lo - margin, box[k].hi + margin};
        }
        choices[i] = field->settled_choices(box);
    });
    // Field 0 is the whole field: for cells where nothing is settled, and those past the limit.
    CellFields result{{field}, std::vector<std::uint32_t>(cells.size(), 0)};
    const std::size_t length = std::size_t(field->tape_length());
    std::map<std::vector<std::uint8_t>, std::uint32_t> made{{std::vector<std::uint8_t>(length, 0), 0}};
    std::size_t instructions = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (const auto found = made.find(choices[i]); found != made.end()) {
            result.of_cell[i] = found->second;
            continue;
        }
        if (instructions >= kMaxPrunedInstructions) continue;
        const std::shared_ptr<const ExpressionField> pruned = field->pruned(choices[i]);
        const auto pruned_length = std::size_t(pruned->tape_length());
        memory.charge(pruned_length * sizeof(Instruction), "isosurface pruned tapes", where);
        instructions += pruned_length;
        result.of_cell[i] = made[choices[i]] = std::uint32_t(result.fields.size());
        result.fields.push_back(pruned);
    }
    return result;
}

}  // namespace isotrace
