#include "geometry/field/transformed_field.h"

#include <cmath>
#include <vector>

#include "renderer/math/box_corner.h"

namespace isotrace {
namespace {

class TransformedField final : public ImplicitField {
public:
    TransformedField(std::unique_ptr<ImplicitField> inner, const Transform& to_outer)
        : inner_(std::move(inner)), to_outer_(to_outer), to_inner_(to_outer.inverse()) {
        // The Frobenius norm bounds how far the inverse map can stretch a ball's radius.
        double sum = 0;
        for (const Vec3d& axis : {Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 1}})
            sum += dot(to_inner_.vector(axis), to_inner_.vector(axis));
        inner_stretch_ = std::sqrt(sum);
    }

    double value(const Vec3d& p) const override { return inner_->value(to_inner_.point(p)); }
    void values(std::span<const Vec3d> points, std::span<double> out) const override {
        std::vector<Vec3d> inner(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) inner[i] = to_inner_.point(points[i]);
        inner_->values(inner, out);
    }
    // ∇(f∘A⁻¹) = A⁻ᵀ∇f, which is what Transform::normal applies.
    Vec3d gradient(const Vec3d& p) const override { return to_outer_.normal(inner_->gradient(to_inner_.point(p))); }
    FieldBox bounds() const override {
        const FieldBox inner = inner_->bounds();
        FieldBox box = FieldBox::none();
        for (int corner = 0; corner < 8; ++corner)
            box.extend(to_outer_.point(box_corner(inner.lower, inner.upper, corner)));
        return box;
    }
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return inner_->may_reach_surface(to_inner_.point(centre), radius * inner_stretch_);
    }
    Interval value_range(const IntervalBox& box) const override {
        return inner_->value_range(transformed_box(box, to_inner_));
    }
    // d/dt f(A⁻¹(p + t·d)) is the inner field's slope along A⁻¹d.
    Interval slope_range(const IntervalBox& box, const Vec3d& direction) const override {
        return inner_->slope_range(transformed_box(box, to_inner_), to_inner_.vector(direction));
    }

private:
    std::unique_ptr<ImplicitField> inner_;
    Transform to_outer_, to_inner_;
    double inner_stretch_ = 1;
};

}  // namespace

IntervalBox transformed_box(const IntervalBox& box, const Transform& map) {
    IntervalBox image = IntervalBox::point(map.point(box.lower()));
    for (int corner = 1; corner < 8; ++corner) image.extend(map.point(box_corner(box.lower(), box.upper(), corner)));
    return image;
}

std::unique_ptr<ImplicitField> transformed_field(std::unique_ptr<ImplicitField> inner, const Transform& to_outer) {
    if (to_outer.is_identity()) return inner;
    return std::make_unique<TransformedField>(std::move(inner), to_outer);
}

}  // namespace isotrace
