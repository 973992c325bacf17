#pragma once
// The undeformed superquadric (superellipsoid) in its own frame: semi-axes a1, a2, a3 and the exponents ε1
// (north–south, along z) and ε2 (east–west, in the xy plane). Its inside–outside function is
//   F = ((x/a1)^(2/ε2) + (y/a2)^(2/ε2))^(ε2/ε1) + (z/a3)^(2/ε1),  F < 1 inside.
// Everything here works with the gauge G = F^(ε1/2) instead: a nested p-norm ‖(‖(u, v)‖_{2/ε2}, w)‖_{2/ε1} of
// u = |x|/a1, v = |y|/a2, w = |z|/a3. G < 1 exactly where F < 1, but G is homogeneous of degree 1 (so it grows
// like distance, never overflows, and stays well scaled for root refinement) and it is non-decreasing in each of
// u, v, w, so its range over a box of magnitudes is given by the box's two extreme corners.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "geometry/field/difference_of_convex.h"
#include "geometry/polynomial/polynomial.h"  // ValueAndDerivative
#include "geometry/superquadric/cone_about_z.h"
#include "geometry/superquadric/enclosing_polytope.h"
#include "geometry/superquadric/norm_exponent.h"
#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

class Superellipsoid {
public:
    Superellipsoid() : Superellipsoid({1, 1, 1}, 1, 1) {}
    Superellipsoid(const Vec3d& radii, double north_south, double east_west);

    const Vec3d& radii() const { return radii_; }
    double north_south() const { return north_south_; }  // ε1
    double east_west() const { return east_west_; }      // ε2

    // The supported exponent range (thinner or more pinched shapes are outside the tested tolerance).
    static constexpr double kMinExponent = 0.02, kMaxExponent = 4;

    double gauge(const Vec3d& p) const;
    // The largest of |xᵢ|/aᵢ, the bounding box's gauge: at most the gauge (a p-norm is at least its largest
    // component), without a power.
    double box_gauge(const Vec3d& p) const {
        const Vec3d m = magnitudes(p);
        return std::max({m.x, m.y, m.z});
    }
    // A direction with each component divided by its radius: the rates at which u, v and w change along it, up to
    // their signs. Along a straight ray they are the same at every point, so a search takes them once.
    struct RadiusRates {
        Vec3d per_radius;
    };
    RadiusRates rates_along(const Vec3d& direction) const {
        return {direction * inverse_radii_};
    }
    // The gauge at p (bit for bit gauge(p)) and its derivative along `direction` (NaN where it is unbounded or
    // undefined, at coordinate planes for exponents above 2), for Newton steps along a ray.
    ValueAndDerivative gauge_along(const Vec3d& p, const RadiusRates& direction) const;
    ValueAndDerivative gauge_along(const Vec3d& p, const Vec3d& direction) const {
        return gauge_along(p, rates_along(direction));
    }
    // Which quadrics: those along the radii (the tightest), or their round forms about z (the circle through the
    // larger of a1 and a2 around, the smaller within), which every turn about z maps onto themselves, so that they
    // hold a twisted solid as well.
    enum class QuadricForm { AlongRadii, RoundAboutZ };
    // The part [lo, hi] of the segment start + τ·direction, τ ∈ [0, length], inside the elliptic cylinder around z
    // and the ellipsoid that hold the solid G ≤ 1, enlarged by a margin far above the gauge's rounding (so that the
    // gauge exceeds 1 where the part ends before `length` or begins after 0); nothing where the segment misses them.
    // For segments within the bounding box, where both quadrics are a few units across.
    std::optional<Interval> enclosing_stretch(const Vec3d& start, const Vec3d& direction, double length,
                                              QuadricForm form = QuadricForm::AlongRadii) const;
    // The part of the same segment inside an ellipsoid within the solid, shrunk by the same margin (so that the
    // gauge is below 1 throughout it); nothing where the segment misses it.
    std::optional<Interval> inscribed_stretch(const Vec3d& start, const Vec3d& direction, double length,
                                              QuadricForm form = QuadricForm::AlongRadii) const;
    // The τ in [0, length] where the same segment comes nearest the centre as that ellipsoid measures it: where a
    // segment that misses the ellipsoid passes deepest into the solid, as a rule.
    double nearest_to_centre(const Vec3d& start, const Vec3d& direction, double length,
                             QuadricForm form = QuadricForm::AlongRadii) const;
    // Planes that hold the solid where an exponent is above 1 (none otherwise): a segment that misses them holds no
    // crossing.
    const EnclosingPolytope& enclosing_polytope() const { return enclosing_polytope_; }
    // The elliptic cylinder of enclosing_stretch, for deformations to carry.
    ConeAboutZ enclosing_cylinder() const { return {along_radii_.cylinder.x, along_radii_.cylinder.y, 1, 0}; }
    // Exponents ≤ 2 make the gauge a (nested) norm, so the solid is convex.
    bool is_convex() const { return north_south_ <= 2 && east_west_ <= 2; }
    // Round cross-sections (a1 = a2, ε2 = 1): the gauge, and every level set of it, is a solid of revolution about z.
    bool is_round_about_z() const { return radii_.x == radii_.y && east_west_ == 1; }
    // Exponents ≥ 2 make each p-norm one with p ≤ 1, concave on the non-negative orthant, and so the gauge concave
    // within each octant: along a ray, between the coordinate planes.
    bool is_concave_in_octants() const { return north_south_ >= 2 && east_west_ >= 2; }
    // With one exponent below 2 and the other above (neither convex nor concave in octants): φ = c − s with c and s
    // convex along the ray between the coordinate planes, where φ < 0 exactly inside (for points within the
    // superellipsoid's box), at p with the slopes along `direction` (non-finite at cusps); and the gauge at p, bit
    // for bit gauge(p), which shares its horizontal norm.
    struct GaugeAndDifference {
        double gauge;
        DifferenceOfConvexSample difference;
    };
    GaugeAndDifference gauge_and_difference(const Vec3d& p, const RadiusRates& direction) const;
    // The range of the gauge over the (signed) points of `box`: the values at the two extreme corners of its box of
    // magnitudes, widened outward by the gauge's rounding error.
    Interval gauge_range(const IntervalBox& box) const;
    // gauge_range's lower and upper ends alone.
    double least_gauge(const IntervalBox& box) const;
    double most_gauge(const IntervalBox& box) const;
    // A bound of the gauge's gradient over the (signed) points of `box`; components may be infinite (exponents
    // above 2 near the coordinate planes).
    IntervalBox gradient_range(const IntervalBox& box) const;

    // Outward unit normal (direction of ∇F). On the coordinate planes, where F has creases or cusps for
    // exponents ≥ 2, it is the limit from the positive side; at the poles of a pinched shape it is ±z.
    Vec3d normal(const Vec3d& p) const;

    // ε1 = ε2 = 1: an ellipsoid, whose crossings with a line a quadratic gives.
    bool is_ellipsoid() const { return north_south_ == 1 && east_west_ == 1; }

    // The paper's parametric surface (eq. 1) with signed powers: η ∈ [−π/2, π/2] latitude, ω ∈ [−π, π].
    Vec3d surface_point(double eta, double omega) const;

    // The cells of a per_axis³ grid over the bounding box that the surface passes through (the gauge's range
    // over the cell contains 1): a deformed object's bounds are the union of its deformed surface cells.
    std::vector<IntervalBox> surface_cells(int per_axis) const;

    // The bytes of its exponents' tables (shared with every superellipsoid of the same exponents: an upper bound).
    std::size_t table_bytes() const {
        return (p1_.tables ? sizeof(NormTables) : 0) + (p2_.tables ? sizeof(NormTables) : 0);
    }
    // The most table_bytes() can be.
    static constexpr std::size_t kMostTableBytes = 2 * sizeof(NormTables);

    IntervalBox bounding_box() const {
        return {{-radii_.x, radii_.x}, {-radii_.y, radii_.y}, {-radii_.z, radii_.z}};
    }

private:
    // u, v, w = |x|/a1, |y|/a2, |z|/a3 (as products with the inverse radii).
    Vec3d magnitudes(const Vec3d& p) const {
        return {std::abs(p.x) * inverse_radii_.x, std::abs(p.y) * inverse_radii_.y, std::abs(p.z) * inverse_radii_.z};
    }
    // The normal from the partial derivatives' logarithms: also where they are unbounded or vanish together.
    Vec3d limit_normal(const Vec3d& p) const;

    Vec3d radii_;
    // 1/aᵢ: every point's u, v, w are |xᵢ|·(1/aᵢ), a product rather than a division (the gauge's first and
    // slowest step otherwise), the same in every function so that they agree to the bit.
    Vec3d inverse_radii_;
    double north_south_, east_west_;
    NormExponent p1_, p2_;  // of the outer norm (2/ε1) and the inner, horizontal one (2/ε2)
    Vec3d log_radii_;       // the normal's logarithms of the radii, taken once
    // The solid lies where Σ (kᵢ·xᵢ)² ≤ 1 for k = `cylinder` (its z component 0) and for k = `ellipsoid`, and holds
    // the points where it is below 1 for k = `inscribed`.
    struct QuadricScales {
        Vec3d cylinder, ellipsoid, inscribed;
    };
    QuadricScales along_radii_, round_about_z_;
    EnclosingPolytope enclosing_polytope_;
    const QuadricScales& scales(QuadricForm form) const {
        return form == QuadricForm::AlongRadii ? along_radii_ : round_about_z_;
    }
};

}  // namespace isotrace
