// The implicit field of a set of superquadrics (their union) for the polygonisers: the shape's field turned round
// (negative inside), min over the set of G(D⁻¹(p)) − 1, continued beyond each deformed box by the distance to it
// so that it stays positive, continuous and rising there (a dual-contouring vertex clamped to a cell may sit just
// outside the box, where a constant field had no gradient and |f|/|∇f| was infinite).
//
// value_range carries the box into each superquadric's deformed frame, bounds the gauge over the undeformed image
// of its part inside the deformed box (interval arithmetic through the chain, as the crossing search does) and
// adds the range of the distance to that box; slope_range is left unbounded (the gauge is not Lipschitz in
// space), which a search using this field as a term pays for in halvings only.
#include <algorithm>
#include <cmath>

#include "geometry/field/transformed_field.h"
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

    Interval value_range(const IntervalBox& box) const override {
        Interval range{INFINITY, INFINITY};
        for (const Superquadric& s : shape_.superquadrics()) {
            const Interval own = continued_range(s, box);
            range = min(range, own);
        }
        return range;
    }

private:
    // The range of s.continued_field over `box`: local_field over the box clamped to the deformed box, plus the
    // distance to the deformed box.
    static Interval continued_range(const Superquadric& s, const IntervalBox& box) {
        const IntervalBox local = transformed_box(box, s.placement().inverse());
        const IntervalBox& deformed = s.deformation().deformed_box();
        // The nearest points of the deformed box to the box's points: clamping is monotone in each coordinate.
        IntervalBox clamped = IntervalBox::point(deformed.nearest(local.lower()));
        clamped.extend(deformed.nearest(local.upper()));
        double near2 = 0, far2 = 0;
        for (int k = 0; k < 3; ++k) {
            const double below = deformed[k].lo - local[k].lo, above = local[k].hi - deformed[k].hi;
            const double gap_near = std::max({deformed[k].lo - local[k].hi, local[k].lo - deformed[k].hi, 0.0});
            const double gap_far = std::max({below, above, 0.0});
            near2 += gap_near * gap_near;
            far2 += gap_far * gap_far;
        }
        bool clipped = false;
        const std::optional<IntervalBox> undeformed = s.deformation().inverse_box(clamped, clipped);
        Interval field{1, 1};  // outside a stage box the field is 1
        if (undeformed) {
            const Interval gauge = s.shape().gauge_range(*undeformed);
            field = {gauge.lo - 1, clipped ? std::max(gauge.hi - 1, 1.0) : gauge.hi - 1};
        }
        return field + Interval{std::sqrt(near2), std::sqrt(far2)};
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
        const Interval gauge = s.shape().gauge_range(*undeformed);
        // A clipped part lies outside the object (gauge above 1 there), as in Superquadric's crossing search.
        return gauge.lo <= 1 && (clipped || gauge.hi >= 1);
    }

    const SuperquadricShape& shape_;
};

}  // namespace

std::unique_ptr<ImplicitField> SuperquadricShape::implicit_field() const { return std::make_unique<SuperquadricField>(*this); }

}  // namespace isotrace
