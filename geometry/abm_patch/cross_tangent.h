#pragma once
// A cross-boundary tangent attribute (a "ribbon") along one side of a patch: the derivative r(λ) of the surface
// away from the side, per unit of domain distance, at the side's parameter λ. The side then contributes the
// attribute c(λ) + d·r(λ) instead of the point c(λ); with a weight exponent p > 1 the other sides' pull vanishes
// to first order at the side, so the patch leaves the side along r and its tangent plane there is spanned by
// c′ and r.
//
// r is built from a normal N along the curve, shared by the patches that meet there: r = m·(N⊥ × ĉ′)/|N⊥ × ĉ′|
// with N⊥ the part of N normal to the curve, pointing into the patch, of a reach m of the patch's own. Every
// patch's tangent plane on the curve is then the plane normal to N⊥, exactly, whatever m.
#include <memory>
#include <utility>

#include "geometry/curves/bspline_curve.h"
#include "geometry/curves/space_curve.h"

namespace isotrace {

class CrossTangent {
public:
    // `normal`: N in the curve's own parameter t, facing the patch's front once multiplied by `facing` (±1);
    // `reach`: m in the side's parameter λ (t = 1 − λ when the side runs the curve backwards).
    CrossTangent(std::shared_ptr<const SpaceCurve> curve, bool reversed, std::shared_ptr<const BSplineCurve<Vec3d>> normal,
                 double facing, BSplineCurve<double> reach);

    Vec3d operator()(double along) const;
    // r(λ) and dr/dλ (by central differences: the curve layer has no second derivative for ĉ′).
    std::pair<Vec3d, Vec3d> value_and_derivative(double along) const;

private:
    std::shared_ptr<const SpaceCurve> curve_;
    bool reversed_;
    std::shared_ptr<const BSplineCurve<Vec3d>> normal_;
    double facing_;
    BSplineCurve<double> reach_;
};

// The unit tangent of a side (the curve run backwards when `reversed`) at its parameter λ. Where the curve stops (a
// zero derivative, as at a doubled control point), the direction of its chord over a short step; zero for a curve
// that does not move there at all.
Vec3d side_direction(const SpaceCurve& curve, bool reversed, double along);

// The unit direction into a patch across its side, normal to `normal` (facing the patch's front) and to the
// side's unit tangent; `fallback` where `normal` runs along the tangent or there is no tangent.
Vec3d inward_across(const Vec3d& normal, const Vec3d& tangent, const Vec3d& fallback);

}  // namespace isotrace
