// The pruned field of each octree cell: shorter tapes near one part of a smooth union, shared between cells that
// settle the same choices, and the whole field's values inside each cell.
#include "geometry/isosurface/cell_fields.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/isosurface/interval_octree.h"

namespace isotrace {
namespace {

TEST(CellFields, EachCellRunsTheTapePrunedToIt) {
    const auto field = compile_expression(
        {"smin(length(max(abs(p) - vec(0.4, 0.3, 0.4), 0)) - 0.05, length(p - vec(0, 0.6, 0)) - 0.3, 0.1)",
         {"scene.json", 1, 1}, "f"},
        {});
    MemoryBudget memory;
    const Container container = Container::box({-0.6, -0.6, -0.6}, {0.6, 1.0, 0.6});
    const std::vector<IntervalBox> cells = surface_cells(*field, container, {5, 1 << 16}, memory);
    const CellFields fields = pruned_cell_fields(field, cells, memory);
    ASSERT_EQ(fields.of_cell.size(), cells.size());
    EXPECT_GT(fields.fields.size(), 10u);
    EXPECT_LT(fields.fields.size(), cells.size() / 4);  // shared between cells
    std::size_t shorter = 0;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0, 1);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const auto& pruned = dynamic_cast<const ExpressionField&>(*fields.fields[fields.of_cell[i]]);
        shorter += pruned.tape_length() * 2 < field->tape_length();
        const IntervalBox& c = cells[i];
        for (int k = 0; k < 4; ++k) {
            const Vec3d p{c.x.lo + unit(rng) * c.x.width(), c.y.lo + unit(rng) * c.y.width(),
                          c.z.lo + unit(rng) * c.z.width()};
            ASSERT_EQ(pruned.value(p), field->value(p));
        }
    }
    EXPECT_GT(shorter * 2, cells.size());  // most cells run less than half the tape
}

}  // namespace
}  // namespace isotrace
