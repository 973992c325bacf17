#pragma once
// The sweep surface of Yoon & Kim, eq. (1): S(θ, t) = C(t) + R(t)·(r(θ,t) cos θ, r(θ,t) sin θ, 0), t ∈ [0, 1].
// C is the cubic B-spline through the key centres at chord-length parameters; R(t) the rotation of the unit
// quaternion Q(t)/|Q(t)|, Q the quadratic B-spline through the key orientations (signs made consistent, so that
// it never passes through the long way round); r(θ, t) see RadiusFunction.
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/curves/bspline_curve.h"
#include "geometry/sweep/key_section.h"
#include "renderer/math/quaternion.h"
#include "geometry/sweep/radius_function.h"

namespace isotrace {

// How the centre curve and the radii run between key sections: the paper's cubic interpolating B-spline (C²,
// but it overshoots: widening two key sections narrows their neighbours), or shape-preserving piecewise cubics
// (C¹, never beyond the values of the two key sections around; geometry/curves/shape_preserving_curve.h).
enum class SweepSpline { cubic, shape_preserving };

class SweepSurface {
public:
    // Smallest |Q(t)| accepted; below it the normalised orientation swings too fast to be meaningful (two
    // consecutive keys nearly half a turn apart).
    static constexpr double kMinOrientationNorm = 0.25;

    // Throws std::invalid_argument "key_sections[k].field: problem" for: fewer than two keys, radii of differing
    // counts, fewer than 3 or more than 512 radii, a radius that is not finite and > 0, an orientation that is not
    // finite or not of unit length (within 1e-6), coinciding consecutive centres, consecutive normals more than 90°
    // apart (reversed), or |Q(t)| below the limit.
    // `parameters`: the keys' t, strictly increasing from 0 to 1; empty = chord lengths of the centres. Edited
    // sweeps keep the parameters of the sweep as first placed, so that an edit of one key section does not shift
    // the sections of every bound vertex along the sweep.
    explicit SweepSurface(std::vector<KeySection> keys, std::vector<double> parameters = {},
                          SweepSpline spline = SweepSpline::cubic);

    // About the operations the constructor's interpolation takes for `keys` key sections of `radius_samples`
    // radii: a banded solve over the keys per radius sample and a cyclic one over the radii per key.
    static std::uint64_t construction_steps(std::size_t keys, std::size_t radius_samples) {
        return std::uint64_t(keys) * radius_samples * (keys + radius_samples);
    }

    const std::vector<KeySection>& keys() const { return keys_; }
    const std::vector<double>& key_parameters() const { return parameters_; }
    SweepSpline spline() const { return spline_; }
    int radius_samples() const { return radius_.samples(); }

    Vec3d centre(double t) const { return centre_(t); }
    Vec3d centre_velocity(double t) const { return centre_.first(t); }
    Quaternion orientation(double t) const { return normalize(orientation_(t)); }
    Vec3d normal(double t) const { return orientation(t).axis_z(); }  // N(t), the third column of R(t)
    // ω with RᵀR′ = [ω]ₓ: the section's angular velocity in its own frame, 2·vec(q̄·q′) for q = Q/|Q|.
    Vec3d angular_velocity(double t) const;
    double radius(double theta, double t) const { return radius_(theta, t); }
    Vec3d point(double theta, double t) const;
    // C(t) + R(t)·local.
    Vec3d place(const Vec3d& local, double t) const { return centre(t) + orientation(t).rotate(local); }
    // Diagonal of the box around the key centres grown by the largest radius: the length scale of tolerances.
    double size() const { return size_; }

private:
    std::vector<KeySection> keys_;
    std::vector<double> parameters_;
    SweepSpline spline_;
    DifferentiableCurve<Vec3d> centre_;
    DifferentiableCurve<Quaternion> orientation_;
    RadiusFunction radius_;
    double size_ = 0;
};

}  // namespace isotrace
