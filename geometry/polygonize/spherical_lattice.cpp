#include "geometry/polygonize/spherical_lattice.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace isotrace {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

SphericalLattice::SphericalLattice(const SphericalRange& range, int depth)
    : Lattice(depth),
      range_(range),
      dr_((range.r_max - range.r_min) / cells_per_axis()),
      dtheta_(kPi / cells_per_axis()),
      dphi_(2 * kPi / cells_per_axis()) {}

Vec3d SphericalLattice::cartesian(double r, double theta, double phi) const {
    const double s = std::sin(theta);
    return range_.origin + Vec3d(s * std::cos(phi), s * std::sin(phi), std::cos(theta)) * r;
}

Vec3d SphericalLattice::position(const Vec3d& c) const {
    return cartesian(range_.r_min + c[0] * dr_, c[1] * dtheta_, c[2] * dphi_);
}

LatticeIndex SphericalLattice::canonical_corner(LatticeIndex corner) const {
    const int n = cells_per_axis();
    corner[2] = ((corner[2] % n) + n) % n;
    if (corner[1] == 0 || corner[1] == n) corner[2] = 0;  // the pole is one point for every φ
    return corner;
}

bool SphericalLattice::canonical_edge(LatticeIndex& corner, int axis) const {
    const int n = cells_per_axis();
    const bool on_pole = corner[1] == 0 || corner[1] == n;
    if (axis == 2 && on_pole) return false;  // a φ-edge on the pole has zero length
    corner[2] = ((corner[2] % n) + n) % n;
    if (axis == 0 && on_pole) corner[2] = 0;  // one polar r-edge for all φ
    return true;
}

bool SphericalLattice::wrap_cell(int axis, int& value) const {
    const int n = cells_per_axis();
    if (axis == 2) {
        value = ((value % n) + n) % n;
        return true;
    }
    return value >= 0 && value < n;
}

void SphericalLattice::cells_around_edge(const LatticeIndex& corner, int axis, std::vector<EdgeNeighbour>& out) const {
    if (!is_polar_edge(corner, axis)) return Lattice::cells_around_edge(corner, axis, out);
    // The ring around the polar axis, counter-clockwise about +r: increasing φ at θ = 0 (where +r is the pole
    // direction), decreasing at θ = π (where it is the opposite).
    out.clear();
    const int n = cells_per_axis();
    const bool north = corner[1] == 0;
    for (int k = 0; k < n; ++k) {
        const int phi = north ? k : n - 1 - k;
        out.push_back({{corner[0], north ? 0 : n - 1, phi}, north ? 0 : 1});
    }
}

bool SphericalLattice::may_hold_surface(const ImplicitField& field, int level, const LatticeIndex& cell) const {
    const double width = double(1 << (depth() - level));
    const double r0 = range_.r_min + cell[0] * width * dr_, r1 = r0 + width * dr_;
    const double t0 = cell[1] * width * dtheta_, t1 = t0 + width * dtheta_;
    const double p0 = cell[2] * width * dphi_, p1 = p0 + width * dphi_;
    const Vec3d centre = cartesian((r0 + r1) / 2, (t0 + t1) / 2, (p0 + p1) / 2);
    // Any point of the cell is reached from the centre by arcs in φ (length ≤ r·sinθ·Δφ/2), θ (≤ r·Δθ/2) and a
    // radial step (≤ Δr/2).
    const double max_sin = (t0 <= kPi / 2 && kPi / 2 <= t1) ? 1.0 : std::max(std::sin(t0), std::sin(t1));
    const double radius = (r1 - r0) / 2 + r1 * (t1 - t0) / 2 + r1 * max_sin * (p1 - p0) / 2;
    return field.may_reach_surface(centre, radius);
}

Vec3d SphericalLattice::clamp_to_cell(const Vec3d& p, const LatticeIndex& cell) const {
    const Vec3d d = p - range_.origin;
    const double r0 = range_.r_min + cell[0] * dr_, t0 = cell[1] * dtheta_, p0 = cell[2] * dphi_;
    const double r = std::clamp(length(d), r0, r0 + dr_);
    const double theta = std::clamp(std::atan2(std::hypot(d.x, d.y), d.z), t0, t0 + dtheta_);
    const double phi = std::atan2(d.y, d.x);
    // φ is an angle: outside [p0, p1], take the nearer end round the circle.
    double offset = std::remainder(phi - (p0 + dphi_ / 2), 2 * kPi);
    offset = std::clamp(offset, -dphi_ / 2, dphi_ / 2);
    return cartesian(r, theta, p0 + dphi_ / 2 + offset);
}

}  // namespace isotrace
