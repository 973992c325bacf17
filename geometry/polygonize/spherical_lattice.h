#pragma once
// The spherical lattice of spherical-octree dual contouring: index axes (r, θ, φ) about an origin o, with
// r ∈ [r_min, r_max] (r_min > 0), θ ∈ [0, π], φ ∈ [0, 2π), each cut into 2^L. A point is
//   o + r·(sinθ cosφ, sinθ sinφ, cosθ)
// (y = r sinθ sinφ; the paper's eq. 5 prints cos φ). φ is periodic by integer index, so the cells at φ = 0 and
// 2π are neighbours; all corners with θ = 0 (or π) are one point per r, and an r-edge there is the polar axis,
// shared by the ring of 2^L cells around it.
#include "geometry/polygonize/lattice.h"

namespace isotrace {

struct SphericalRange {
    Vec3d origin;
    double r_min = 0, r_max = 0;
};

class SphericalLattice final : public Lattice {
public:
    SphericalLattice(const SphericalRange& range, int depth);

    const SphericalRange& range() const { return range_; }
    Vec3d position(const Vec3d& coordinates) const override;
    LatticeIndex canonical_corner(LatticeIndex corner) const override;
    bool canonical_edge(LatticeIndex& corner, int axis) const override;
    void cells_around_edge(const LatticeIndex& corner, int axis, std::vector<EdgeNeighbour>& out) const override;
    bool may_hold_surface(const ImplicitField& field, int level, const LatticeIndex& cell) const override;
    Vec3d clamp_to_cell(const Vec3d& p, const LatticeIndex& cell) const override;
    bool is_polar_edge(const LatticeIndex& corner, int axis) const override {
        return axis == 0 && (corner[1] == 0 || corner[1] == cells_per_axis());
    }

    // Unit direction of the polar axis (θ = 0).
    static Vec3d pole_direction() { return {0, 0, 1}; }

protected:
    bool wrap_cell(int axis, int& value) const override;

private:
    Vec3d cartesian(double r, double theta, double phi) const;

    SphericalRange range_;
    double dr_, dtheta_, dphi_;  // one finest cell
};

}  // namespace isotrace
