#pragma once
// Barr's bend ("Global and local deformations of solid primitives", 1984), with the z axis as the bent axis as in
// the paper's Fig. 1(d) (whose eq. 5 is garbled). In the bend frame — s along the bend direction
// u = (cos α, sin α, 0), w along v = (−sin α, cos α, 0), and z — the segment z ∈ [z_lo, z_hi] of the axis is
// wrapped onto a circle of radius R = 1/k whose centre is at (s, z) = (R, z0):
//   ẑ = clamp(z, z_lo, z_hi),  θ = k·(ẑ − z0),
//   S = R − (R − s)·cos θ + (z − ẑ)·sin θ,   Z = z0 + (R − s)·sin θ + (z − ẑ)·cos θ,   W = w.
// Outside the region the object continues along the tangent. The inverse is closed-form (Barr): the angle of
// the point about the centre, clamped to the region's angles, gives θ; projecting onto the rotated axes gives
// R − s and z − ẑ. It is a true inverse over the object when k·s < 1 everywhere on it (no point folds through
// the centre) and the region's total angle is at most 180° (the angle is read within ±180° of the middle one).
#include <optional>
#include <string>

#include "geometry/superquadric/bend_sector.h"
#include "geometry/superquadric/cone_about_z.h"

#include "renderer/math/interval.h"
#include "geometry/superquadric/jacobian.h"

namespace isotrace {

class Bend {
public:
    // Largest k·s allowed over the object, and the largest total bend angle.
    static constexpr double kMaxCurvatureTimesExtent = 0.999;

    // curvature > 0 (a negative curvature is the same bend in the opposite direction); direction α in radians;
    // the region's ends z_lo < z_hi.
    Bend(double curvature, double direction, double centre, Interval region);

    Vec3d forward(const Vec3d& p) const;
    Vec3d inverse(const Vec3d& q) const;
    Jacobian jacobian(const Vec3d& p) const;
    IntervalBox forward_box(const IntervalBox& box) const;
    IntervalBox inverse_box(const IntervalBox& box) const;
    // Bounds d/dt of inverse(q(t)) for q' ∈ `tangent`, where `preimage` bounds the inverse points (inside the
    // chain's stage box, where k·s < 1).
    IntervalBox inverse_tangent(const IntervalBox& preimage, const IntervalBox& tangent) const;
    std::string problem(const IntervalBox& input) const;
    // Bending the z-axis into an arc moves the axis a solid of revolution turns about.
    bool keeps_solids_of_revolution() const { return false; }
    // Turning cross-sections about the centre moves their heights.
    bool keeps_heights() const { return false; }
    // Nor does a cone about z hold the bent object.
    std::optional<ConeAboutZ> carry(const ConeAboutZ&) const { return std::nullopt; }
    // The annular sector about the bend's centre that holds the object bent, where `before` bounds it before the bend
    // (and `cone`, when there is one, too) and `heights` are its heights; nothing where part of it lies beyond the
    // region, which continues along the tangents instead of turning about the centre.
    std::optional<BendSector> sector(const IntervalBox& before, Interval heights,
                                     const std::optional<ConeAboutZ>& cone) const;

private:
    struct FrameBox {
        Interval s, w, z;
    };
    FrameBox to_frame(const IntervalBox& box) const;
    IntervalBox from_frame(const FrameBox& box) const;
    Vec3d from_frame(double s, double w, double z) const { return u_ * s + v_ * w + Vec3d(0, 0, z); }
    double region_angle(double z) const;
    // How far z lies beyond the bent region (0 inside it): the straight continuation past either end.
    double beyond_region(double z) const;
    static double versine(SinCos at);
    // (1 − cos θ)/k over an interval of angles, from sin and cos at its ends and the range of cos over it.
    Interval versine_over_curvature(SinCos at_lo, SinCos at_hi, Interval cos) const;

    double curvature_, centre_;
    Interval region_;
    double angle_lo_, angle_hi_, angle_middle_;
    double cos_middle_, sin_middle_;
    Vec3d u_, v_;
};

}  // namespace isotrace
