#pragma once
// Barr's twist about z (the paper's eq. 4): the cross-section at height z turns by θ = rate·(z + a3), so the
// bottom (z = −a3) stays put and the top turns by rate·2·a3.
#include <string>

#include "renderer/math/interval.h"
#include "geometry/superquadric/jacobian.h"

namespace isotrace {

class Twist {
public:
    Twist(double rate, double half_height) : rate_(rate), half_height_(half_height) {}

    Vec3d forward(const Vec3d& p) const { return rotate(p, angle(p.z)); }
    Vec3d inverse(const Vec3d& q) const { return rotate(q, -angle(q.z)); }
    Jacobian jacobian(const Vec3d& p) const;
    IntervalBox forward_box(const IntervalBox& box) const { return rotate_box(box, 1); }
    IntervalBox inverse_box(const IntervalBox& box) const { return rotate_box(box, -1); }
    // Bounds d/dt of inverse(q(t)) for q' ∈ `tangent`, where `preimage` bounds the inverse points.
    IntervalBox inverse_tangent(const IntervalBox& preimage, const IntervalBox& tangent) const;
    // A twist is a rotation per height: every twist is valid.
    std::string problem(const IntervalBox&) const { return {}; }

    double rate() const { return rate_; }

private:
    double angle(double z) const { return rate_ * (z + half_height_); }
    static Vec3d rotate(const Vec3d& p, double theta);
    // The box turned by `sign`·θ(z): interval rotation, cut down to the disc the box's corners reach.
    IntervalBox rotate_box(const IntervalBox& box, double sign) const;

    double rate_, half_height_;
};

}  // namespace isotrace
