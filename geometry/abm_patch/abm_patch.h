#pragma once
// An attribute-based multi-sided patch (Kim & Park after Gao & Rockwood): N boundary curves c_i forming a closed
// loop fill the surface F(x) = Σ f_i(x)·W_i(x) / Σ W_i(x), W_i = 1/d_i(x)^p, with the attributes f_i = c_i(s_i(x)),
// or c_i(s_i) + d_i·r_i(s_i) on a side with a cross-boundary tangent r_i (cross_tangent.h), over a polygonal domain
// (patch_domain.h). The weights are evaluated in product form, W_i ∝ Π_{j≠i} d_j^p, so that on side i (d_i = 0)
// F is c_i exactly and nothing is ever divided by zero; at a corner (two distances zero) F is the corner point.
// The paper's MEL listing multiplies by d_i instead of dividing; that patch does not interpolate its boundary.
//
// Orientation: the front of the patch is the side from which its loop runs counter-clockwise.
#include <memory>
#include <vector>

#include "geometry/abm_patch/patch_domain.h"
#include "geometry/abm_patch/patch_side.h"

namespace isotrace {

struct PatchJet {
    Vec3d point, dx, dy;  // F and its partial derivatives in domain coordinates
};

class AbmPatch {
public:
    static constexpr double kMinExponent = 1, kMaxExponent = 8;

    // Throws std::invalid_argument when the side count differs from the domain's, p is outside [1, 8] (below 1 the
    // surface meets its boundary with an infinite slope; far above, the weights underflow), a curve is
    // degenerate or the loop does not close within `closure_tolerance`.
    AbmPatch(std::shared_ptr<const PatchDomain> domain, std::vector<PatchSide> sides, double exponent = 1,
             double closure_tolerance = 1e-6);

    // The same patch (domain, p) along other sides that run within the closure tolerance of its own (a curve
    // shared by geometry, sides with cross-boundary tangents): the loop checks are not repeated. Throws
    // std::invalid_argument for a different number of sides.
    AbmPatch with_sides(std::vector<PatchSide> sides) const;

    const PatchDomain& domain() const { return *domain_; }
    const std::vector<PatchSide>& sides() const { return sides_; }
    double exponent() const { return exponent_; }

    Vec3d operator()(DomainPoint x) const;
    // F with its derivatives by the quotient rule (undefined at the corners, where F is only continuous).
    PatchJet jet(DomainPoint x) const;

    // Unit front normal at an interior point, from the quotient-rule derivatives.
    Vec3d normal(DomainPoint x) const;
    // The limit of the normal on side i at its parameter t (0 < t < 1): spanned by the curve's tangent and the
    // direction Σ_{j≠i} (c_j − c_i)·Π_{k≠i,j} d_k^p in which the patch leaves the side (for any p; for p > 1 the
    // quotient-rule cross derivative vanishes there); for a side with a cross-boundary tangent r (which needs
    // p > 1), c′ × r.
    Vec3d side_normal(int side, double t) const;
    // The normal at corner k (the end of side k − 1, the start of side k). With p = 1 the patch has no tangent
    // plane there: near the corner F − c ≈ a function of degree one in the domain offset with a component
    // (toward the neighbouring corners) outside the plane of the two curves' tangents, so the normal depends on
    // the direction of approach. This is the limit along the line from the domain's centre (taken 1e-6 of the
    // way in); for p > 1 that limit lies in the plane of the two tangents.
    Vec3d corner_normal(int corner) const;

private:
    // F (and its derivatives when `jet` is non-null).
    Vec3d evaluate(DomainPoint x, PatchJet* jet) const;
    // n normalised, or — when n is negligible against `scale` — the normal slightly inside from x toward the centre.
    Vec3d unit_or_inside(const Vec3d& n, double scale, DomainPoint x) const;

    std::shared_ptr<const PatchDomain> domain_;
    std::vector<PatchSide> sides_;
    double exponent_;
};

}  // namespace isotrace
