#pragma once
// Barr's linear taper along z (the paper's eq. 3, with separate rates for x and y as in Barr 1984):
//   X = fx(z)·x,  Y = fy(z)·y,  Z = z,  f(z) = 1 + rate·(z + a3)/(2·a3),
// so the cross-section keeps its size at the bottom (z = −a3) and is scaled by 1 + rate at the top (z = a3).
#include <optional>
#include <string>

#include "geometry/superquadric/bend_sector.h"
#include "geometry/superquadric/cone_about_z.h"

#include "renderer/math/interval.h"
#include "geometry/superquadric/jacobian.h"

namespace isotrace {

class Taper {
public:
    // The cross-section scale must stay at least this large over the object (the inverse divides by it).
    static constexpr double kMinScale = 0.01;

    Taper(double x_rate, double y_rate, double half_height);

    Vec3d forward(const Vec3d& p) const;
    // Requires the scale factors at q.z to be positive (true inside the chain's stage box).
    Vec3d inverse(const Vec3d& q) const;
    Jacobian jacobian(const Vec3d& p) const;
    IntervalBox forward_box(const IntervalBox& box) const;
    IntervalBox inverse_box(const IntervalBox& box) const;
    // Bounds d/dt of inverse(q(t)) for a curve q(t) with q ∈ inverse of `preimage` and q' ∈ `tangent`, where
    // `preimage` bounds the inverse points (the chain's stage box keeps the scale positive there).
    IntervalBox inverse_tangent(const IntervalBox& preimage, const IntervalBox& tangent) const;
    // Why the taper cannot be applied to points of `input` (empty when it can).
    std::string problem(const IntervalBox& input) const;
    // Scaling the cross-sections by height changes a solid of revolution's profile.
    bool keeps_solids_of_revolution() const { return false; }
    // Scaling x and y keeps every point's height.
    bool keeps_heights() const { return true; }
    // A cylinder that holds the object before the taper, scaled by the larger of the two scales at every height
    // (linear in z, as both are, and equal to them at the bottom): a cone that holds the tapered object. A cone
    // would become a quadratic profile: nothing.
    std::optional<ConeAboutZ> carry(const ConeAboutZ& cone) const;
    // Only a bend leaves the object in an annular sector about its centre.
    std::optional<BendSector> sector(const IntervalBox&, Interval, const std::optional<ConeAboutZ>&) const {
        return std::nullopt;
    }

    // As the only stage on a convex superellipsoid (both exponents at most 2) whose outer norm has the exponent p1 =
    // 2/ε1: the gauge levels s up to which the tapered sublevel set {G ≤ s} is known to be convex (0: none is, as
    // for two different rates).
    double convex_levels(double p1) const;

    double x_rate() const { return x_rate_; }
    double y_rate() const { return y_rate_; }

private:
    double scale(double rate, double z) const { return 1 + rate * (z + half_height_) / (2 * half_height_); }
    Interval scale(double rate, Interval z) const { return Interval::spanning(scale(rate, z.lo), scale(rate, z.hi)); }

    double x_rate_, y_rate_, half_height_;
};

}  // namespace isotrace
