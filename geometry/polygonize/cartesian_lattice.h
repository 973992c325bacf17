#pragma once
// The Cartesian lattice: a cube of space cut into 2^L cells along x, y and z, as the finest level of an octree
// whose root is the cube.
#include "geometry/polygonize/lattice.h"

namespace isotrace {

class CartesianLattice final : public Lattice {
public:
    CartesianLattice(const Vec3d& lower, double size, int depth);
    // The cube around `bounds`, enlarged so that the surface stays clear of the outer faces.
    static CartesianLattice around(const FieldBox& bounds, int depth);

    double cell_size() const { return cell_size_; }
    Vec3d position(const Vec3d& coordinates) const override { return lower_ + coordinates * cell_size_; }
    bool may_hold_surface(const ImplicitField& field, int level, const LatticeIndex& cell) const override;
    Vec3d clamp_to_cell(const Vec3d& p, const LatticeIndex& cell) const override;
    // The point of the octree node `node` of `level` (2^(L − level) finest cells wide) nearest to p.
    Vec3d clamp_to_node(const Vec3d& p, int level, const LatticeIndex& node) const;

private:
    Vec3d lower_;
    double cell_size_;
};

}  // namespace isotrace
