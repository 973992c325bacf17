#include "geometry/polygonize/cartesian_lattice.h"

#include <cmath>

namespace isotrace {

CartesianLattice::CartesianLattice(const Vec3d& lower, double size, int depth)
    : Lattice(depth), lower_(lower), cell_size_(size / cells_per_axis()) {}

CartesianLattice CartesianLattice::around(const FieldBox& bounds, int depth) {
    // Points outside the bounds are outside the solid: a margin keeps every outer corner there.
    const double extent = max_component(bounds.extent());
    const double size = extent * 1.04 + 1e-9 * (1 + max_component(abs(bounds.centre())));
    return CartesianLattice(bounds.centre() - Vec3d{1, 1, 1} * (size / 2), size, depth);
}

bool CartesianLattice::may_hold_surface(const ImplicitField& field, int level, const LatticeIndex& cell) const {
    const double width = cell_size_ * double(1 << (depth() - level));
    const Vec3d corner = lower_ + Vec3d(cell[0], cell[1], cell[2]) * width;
    return field.may_reach_surface(corner + Vec3d{1, 1, 1} * (width / 2), width * std::sqrt(3.0) / 2);
}

Vec3d CartesianLattice::clamp_to_cell(const Vec3d& p, const LatticeIndex& cell) const {
    return clamp_to_node(p, depth(), cell);
}

Vec3d CartesianLattice::clamp_to_node(const Vec3d& p, int level, const LatticeIndex& node) const {
    const double width = cell_size_ * double(1 << (depth() - level));
    const Vec3d lower = lower_ + Vec3d(node[0], node[1], node[2]) * width;
    return min(max(p, lower), lower + Vec3d{1, 1, 1} * width);
}

}  // namespace isotrace
