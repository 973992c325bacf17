// The implicit field of the plane: the signed distance n·(p − origin), negative behind it (the half-space). It has
// no finite box: bounds() is the shape's, the half-space clipped to the world's cube, which a CSG intersection
// narrows to its other operands; a plane alone gives the polygonisers nothing useful to mesh.
#include "geometry/plane/plane_shape.h"

namespace isotrace {
namespace {

class PlaneField final : public ImplicitField {
public:
    explicit PlaneField(const PlaneShape& shape)
        : origin_(shape.frame().origin()), normal_(shape.frame().normal()), bounds_(shape.bounds()) {}

    double value(const Vec3d& p) const override { return dot(p - origin_, normal_); }
    Vec3d gradient(const Vec3d&) const override { return normal_; }
    FieldBox bounds() const override { return {Vec3d(bounds_.lower), Vec3d(bounds_.upper)}; }
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return std::abs(value(centre)) <= radius;
    }
    // Linear: exact ranges.
    Interval value_range(const IntervalBox& box) const override {
        return (box.x + -origin_.x) * normal_.x + (box.y + -origin_.y) * normal_.y + (box.z + -origin_.z) * normal_.z;
    }
    Interval slope_range(const IntervalBox&, const Vec3d& direction) const override {
        return Interval::point(dot(normal_, direction));
    }

private:
    Vec3d origin_, normal_;
    Bounds3f bounds_;
};

}  // namespace

std::unique_ptr<ImplicitField> PlaneShape::implicit_field() const { return std::make_unique<PlaneField>(*this); }

}  // namespace isotrace
