#pragma once
// A rectangle: the points c + s·U + t·V, s, t in [−½, ½], of two perpendicular edge vectors U and V (a
// parallelogram once baked with a shear or a non-uniform scale across its edges, still exact). The front is U × V.
// An emissive rectangle is an area light sampled uniformly by solid angle (SphericalRectangle) where it subtends
// enough of it, by area elsewhere and when baked into a parallelogram.
#include "geometry/plane/flat_shape.h"

namespace isotrace {

class RectangleShape final : public FlatShape {
public:
    RectangleShape(const Vec3d& centre, const Vec3d& edge_u, const Vec3d& edge_v);

    std::string type_name() const override { return "rectangle"; }
    Bounds3f bounds() const override;
    bool covers(const std::array<double, 2>& st) const override;
    // uv = (s + ½, t + ½): 0 to 1 along each edge; dpdu = U, dpdv = V.
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const override;

    bool supports_surface_sampling() const override { return true; }
    SurfaceSample sample_surface(std::array<float, 2> u) const override;
    float surface_area() const override { return float(frame().cell_area()); }

    bool supports_solid_angle_sampling() const override { return perpendicular_; }
    SolidAngleSample sample_solid_angle(const Vec3f& reference, std::array<float, 2> u) const override;
    float solid_angle_pdf(const Vec3f& reference) const override;

private:
    void frame_changed() override;

    bool perpendicular_ = true;  // false for a parallelogram: no solid-angle sampling
};

}  // namespace isotrace
