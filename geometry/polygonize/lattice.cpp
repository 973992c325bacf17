#include "geometry/polygonize/lattice.h"

namespace isotrace {

void Lattice::cells_around_edge(const LatticeIndex& corner, int axis, std::vector<EdgeNeighbour>& out) const {
    out.clear();
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    // Counter-clockwise in the (b, c) plane seen from +axis: (−,−), (+,−), (+,+), (−,+).
    static constexpr int kOffsets[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}};
    for (const auto& offset : kOffsets) {
        LatticeIndex cell = corner;
        cell[b] += offset[0];
        cell[c] += offset[1];
        if (!wrap_cell(axis, cell[axis]) || !wrap_cell(b, cell[b]) || !wrap_cell(c, cell[c])) {
            out.clear();
            return;
        }
        // The edge sits at the cell's far side on an axis where the cell lies below it.
        out.push_back({cell, axis * 4 + (offset[0] < 0 ? 1 : 0) + (offset[1] < 0 ? 2 : 0)});
    }
}

}  // namespace isotrace
