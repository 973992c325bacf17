// The implicit field of a torus: its exact signed distance, for the polygonisers and for isosurfaces that use it as
// a term.
#include <cmath>

#include "geometry/cone/exact_distance_field.h"
#include "geometry/torus/torus_shape.h"

namespace isotrace {
namespace {

class TorusField final : public ExactDistanceField {
public:
    explicit TorusField(const Torus& torus) : torus_(torus) {}

    double value(const Vec3d& p) const override { return torus_distance(torus_, p); }
    Vec3d gradient(const Vec3d& p) const override { return torus_gradient(torus_, p); }
    FieldBox bounds() const override {
        FieldBox box;
        torus_bounds(torus_, box.lower, box.upper);
        return box;
    }

private:
    Torus torus_;
};

}  // namespace

std::unique_ptr<ImplicitField> TorusShape::implicit_field() const { return std::make_unique<TorusField>(torus_); }

}  // namespace isotrace
