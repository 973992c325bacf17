// The implicit field of a set of superquadrics (their union): min over the set of G(D⁻¹(p)) − 1, the gauge of
// the undeformed superellipsoid at the undeformed point (negative inside). The gradient is the analytic normal
// (carried through the deformation chain) scaled by the field's slope along it, a central difference.
// Superquadric::field is a constant 1 outside the deformed box (the ray tracer only needs the sign there), which
// has no gradient: a dual-contouring vertex clamped to a cell may sit just outside the box, and |f|/|∇f| there
// was infinite. Outside the box the field is continued by the distance to it, so it stays positive, continuous
// and rising.
#include <algorithm>
#include <cmath>

#include "geometry/polygonize/implicit_field_registry.h"
#include "geometry/superquadric/superquadric_shape.h"

namespace isotrace {
namespace {

class SuperquadricField final : public ImplicitField {
public:
    explicit SuperquadricField(const SuperquadricShape& shape) : superquadrics_(shape.superquadrics()) {
        const FieldBox box = bounds();
        step_ = 1e-6 * std::max(max_component(box.extent()), 1e-300);
    }

    double value(const Vec3d& p) const override {
        double v = extended_field(superquadrics_[0], p);
        for (std::size_t i = 1; i < superquadrics_.size(); ++i) v = std::min(v, extended_field(superquadrics_[i], p));
        return v;
    }
    Vec3d gradient(const Vec3d& p) const override {
        const Superquadric& s = superquadrics_[nearest(p)];
        const Vec3d n = s.normal(p);
        if (!is_finite(n)) return {};
        return n * ((extended_field(s, p + n * step_) - extended_field(s, p - n * step_)) / (2 * step_));
    }
    FieldBox bounds() const override {
        FieldBox box = FieldBox::none();
        for (const Superquadric& s : superquadrics_) box.extend({s.bounds().lower(), s.bounds().upper()});
        return box;
    }
    // The gauge's range over the undeformed image of the ball's box (interval arithmetic through the chain).
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return std::any_of(superquadrics_.begin(), superquadrics_.end(),
                           [&](const Superquadric& s) { return may_cross(s, centre, radius); });
    }

private:
    static double extended_field(const Superquadric& s, const Vec3d& p) {
        const Vec3d local = s.placement().inverse().point(p);
        const IntervalBox& box = s.deformation().deformed_box();
        const Vec3d clamped(std::clamp(local.x, box.x.lo, box.x.hi), std::clamp(local.y, box.y.lo, box.y.hi),
                            std::clamp(local.z, box.z.lo, box.z.hi));
        return s.local_field(clamped) + length(local - clamped);
    }
    static bool may_cross(const Superquadric& s, const Vec3d& centre, double radius) {
        const Transform to_local = s.placement().inverse();
        IntervalBox local = IntervalBox::point(to_local.point(centre));
        for (int corner = 0; corner < 8; ++corner)
            local.extend(to_local.point(centre + Vec3d(corner & 1 ? radius : -radius, corner & 2 ? radius : -radius,
                                                       corner & 4 ? radius : -radius)));
        bool clipped = false;
        const std::optional<IntervalBox> undeformed = s.deformation().inverse_box(local, clipped);
        if (!undeformed) return false;  // wholly outside the object
        const Interval gauge = s.shape().gauge_range(
            {undeformed->x.magnitude(), undeformed->y.magnitude(), undeformed->z.magnitude()});
        // A clipped part lies outside the object (gauge above 1 there), as in Superquadric's crossing search.
        return gauge.lo <= 1 && (clipped || gauge.hi >= 1);
    }
    std::size_t nearest(const Vec3d& p) const {
        std::size_t best = 0;
        double best_value = extended_field(superquadrics_[0], p);
        for (std::size_t i = 1; i < superquadrics_.size(); ++i) {
            const double v = extended_field(superquadrics_[i], p);
            if (v < best_value) {
                best = i;
                best_value = v;
            }
        }
        return best;
    }

    std::vector<Superquadric> superquadrics_;
    double step_ = 0;
};

}  // namespace
}  // namespace isotrace

ISOTRACE_REGISTER_IMPLICIT_FIELD("superquadric", [](const isotrace::Shape& shape) -> std::unique_ptr<isotrace::ImplicitField> {
    return std::make_unique<isotrace::SuperquadricField>(static_cast<const isotrace::SuperquadricShape&>(shape));
})
