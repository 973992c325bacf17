// The implicit field of a set of superquadrics (their union) for the polygonisers: the shape's field turned round
// (negative inside), min over the set of G(D⁻¹(p)) − 1, continued beyond each deformed box by the distance to it
// so that it stays positive, continuous and rising there (a dual-contouring vertex clamped to a cell may sit just
// outside the box, where a constant field had no gradient and |f|/|∇f| was infinite).
#include <algorithm>
#include <cmath>

#include "geometry/superquadric/superquadric_shape.h"

namespace isotrace {
namespace {

class SuperquadricField final : public ImplicitField {
public:
    explicit SuperquadricField(const SuperquadricShape& shape) : shape_(shape) {}

    double value(const Vec3d& p) const override { return -*shape_.field_value(p); }
    Vec3d gradient(const Vec3d& p) const override { return -shape_.field_gradient(p); }
    FieldBox bounds() const override {
        FieldBox box = FieldBox::none();
        for (const Superquadric& s : shape_.superquadrics()) box.extend({s.bounds().lower(), s.bounds().upper()});
        return box;
    }
    // The gauge's range over the undeformed image of the ball's box (interval arithmetic through the chain).
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return std::any_of(shape_.superquadrics().begin(), shape_.superquadrics().end(),
                           [&](const Superquadric& s) { return may_cross(s, centre, radius); });
    }

private:
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

    const SuperquadricShape& shape_;
};

}  // namespace

std::unique_ptr<ImplicitField> SuperquadricShape::implicit_field() const { return std::make_unique<SuperquadricField>(*this); }

}  // namespace isotrace
