#pragma once
// Barr's twist about z (the paper's eq. 4): the cross-section at height z turns by θ = rate·(z + a3), so the
// bottom (z = −a3) stays put and the top turns by rate·2·a3.
#include <algorithm>
#include <optional>
#include <string>

#include "geometry/superquadric/bend_sector.h"
#include "geometry/superquadric/cone_about_z.h"

#include "renderer/math/interval.h"
#include "renderer/math/sin_cos.h"
#include "geometry/superquadric/jacobian.h"

namespace isotrace {

class Twist {
public:
    Twist(double rate, double half_height) : rate_(rate), half_height_(half_height) {}

    Vec3d forward(const Vec3d& p) const { return turned(p, sin_cos(angle(p.z))); }
    Vec3d inverse(const Vec3d& q) const { return turned(q, sin_cos(-angle(q.z))); }
    Jacobian jacobian(const Vec3d& p) const { return jacobian_at(p, sin_cos(angle(p.z))); }
    // inverse(q) and the Jacobian there, bit for bit, from one sine and cosine: θ is the same at both points (a
    // twist keeps z), and sincos is odd in the sine and even in the cosine, so the inverse's turn by −θ takes
    // them negated.
    struct InverseAndJacobian {
        Vec3d preimage;
        Jacobian jacobian;
    };
    InverseAndJacobian inverse_and_jacobian(const Vec3d& q) const {
        const SinCos at = sin_cos(angle(q.z));
        const Vec3d p = turned(q, {-at.sin, at.cos});
        return {p, jacobian_at(p, at)};
    }
    IntervalBox forward_box(const IntervalBox& box) const { return rotate_box(box, 1); }
    IntervalBox inverse_box(const IntervalBox& box) const { return rotate_box(box, -1); }
    // Bounds d/dt of inverse(q(t)) for q' ∈ `tangent`, where `preimage` bounds the inverse points.
    IntervalBox inverse_tangent(const IntervalBox& preimage, const IntervalBox& tangent) const;
    // A twist is a rotation per height: every twist is valid.
    std::string problem(const IntervalBox&) const { return {}; }
    // Turning about z maps every solid of revolution about z onto itself.
    bool keeps_solids_of_revolution() const { return true; }
    // A turn about z keeps every point's height.
    bool keeps_heights() const { return true; }
    // A cone that holds the object before the twist, made round (its larger radius at every height): it holds the
    // twisted object.
    std::optional<ConeAboutZ> carry(const ConeAboutZ& cone) const {
        const double k = std::min(cone.kx, cone.ky);
        return ConeAboutZ{k, k, cone.alpha, cone.beta};
    }
    // Only a bend leaves the object in an annular sector about its centre.
    std::optional<BendSector> sector(const IntervalBox&, Interval, const std::optional<ConeAboutZ>&) const {
        return std::nullopt;
    }

    double rate() const { return rate_; }

private:
    double angle(double z) const { return rate_ * (z + half_height_); }
    // p turned about z by the angle of `at`.
    static Vec3d turned(const Vec3d& p, SinCos at) {
        return {p.x * at.cos - p.y * at.sin, p.x * at.sin + p.y * at.cos, p.z};
    }
    Jacobian jacobian_at(const Vec3d& p, SinCos at) const;
    // The box turned by `sign`·θ(z): interval rotation, cut down to the disc the box's corners reach.
    IntervalBox rotate_box(const IntervalBox& box, double sign) const;

    double rate_, half_height_;
};

}  // namespace isotrace
