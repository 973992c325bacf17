#pragma once
// The infinite plane: a FlatShape that covers its whole plane, and, as a Solid, the half-space behind it (the side
// its normal points away from), so that CSG can cut with it. It has no finite extent (is_unbounded()): its bounds,
// also the box it gives Embree, are the half-space clipped to the world's cube [−kWorldLimit, kWorldLimit]³, and the
// scene leaves it out of its own extent. It cannot be sampled as an area light (an infinite area); an emissive plane is found by BSDF
// sampling only.
#include "geometry/plane/flat_shape.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

class PlaneShape final : public FlatShape, public Solid {
public:
    // The plane through `point` facing `normal` (unit); u and v run along tangent_axes(normal), one unit of uv per
    // `uv_scale` metres.
    PlaneShape(const Vec3d& point, const Vec3d& normal, double uv_scale);

    std::string type_name() const override { return "plane"; }
    Bounds3f bounds() const override;
    bool is_unbounded() const override { return true; }
    bool covers(const std::array<double, 2>&) const override { return true; }
    // uv = (s, t) of the frame: metres along the tangent axes divided by uv_scale; dpdu and dpdv are the axes.
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const override;
    // The signed distance to the plane, negative behind it.
    std::unique_ptr<ImplicitField> implicit_field() const override;

    // The half-space behind the plane: one span per line that crosses it, ending (or starting) at infinity;
    // a line parallel to the plane is wholly inside or wholly outside.
    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;
};

}  // namespace isotrace
