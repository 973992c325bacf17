#pragma once
// A disk, or an annulus with an inner radius: the points c + ρ(cos φ·a + sin φ·b) with inner ≤ ρ ≤ 1 of a frame
// whose axes a and b are the radius vectors (an ellipse once baked with a non-uniform scale, still exact). The
// front is a × b, the normal given. An emissive disk is an area light sampled uniformly by area.
#include "geometry/plane/flat_shape.h"

namespace isotrace {

class DiskShape final : public FlatShape {
public:
    // `inner_ratio`: the inner radius over the radius, in [0, 1).
    DiskShape(const Vec3d& centre, const Vec3d& normal, double radius, double inner_ratio);

    std::string type_name() const override { return "disk"; }
    Bounds3f bounds() const override;
    bool covers(const std::array<double, 2>& st) const override;
    // uv: u = φ/2π around the normal from the first tangent axis, v = ρ, 0 at the centre and 1 on the rim.
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const override;

    bool supports_surface_sampling() const override { return true; }
    // Uniform by area: ρ = sqrt(inner² + u₀(1 − inner²)), φ = 2πu₁ (an affine map keeps it uniform).
    SurfaceSample sample_surface(std::array<float, 2> u) const override;
    float surface_area() const override;

    double inner_ratio() const { return inner_ratio_; }

private:
    double inner_ratio_ = 0;
};

}  // namespace isotrace
