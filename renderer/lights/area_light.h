#pragma once
// AreaLight: an emissive object whose shape can draw points uniformly by area. The scene makes one per such object
// (and per emissive placement of a definition); it is not a registry plugin. The shape is in world space (baked),
// or in its own space with the placement's to_world (an object whose transform it cannot bake, a placement): its
// points are then carried to the world, where their density per world area is the shape's own divided by the
// transform's local area scale |det A| / |Aᵀ n| (A the linear part, n the world normal), and solid-angle sampling,
// which the shape answers in its own space, is not used.
//
// sample() draws a point on the surface. Where the shape samples by solid angle from the shading point
// (Shape::supports_solid_angle_sampling, e.g. a rectangle), the point is drawn that way and the pdf is the shape's
// density per unit solid angle; elsewhere it is drawn uniformly by area and the area density is converted to solid
// angle at the shading point: pdf = pdf_area * distance^2 / |cos_light|. pdf() asks the shape the same question
// for the same shading point, so it always returns the density sample() draws with (multiple importance sampling
// stays consistent). The radiance is the material's emission at that point towards the shading point. A one-sided
// emitter seen from behind therefore yields radiance 0 while the pdf stays the geometric density above (so pdf()
// needs no knowledge of the material); integrators should skip the shadow ray of a black sample. pdf 0 is returned
// only when no sample exists (the point lies on the light, or the sampled point is seen exactly edge-on).
//
// The emission is probed with a SurfaceHit holding position, geometric and shading normal (both the sampled
// normal), t = distance and the material; uv is not known to the samples and is left at (0, 0).
#include <optional>

#include "renderer/math/transform.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

class AreaLight final : public Light {
public:
    // `shape` is in world space (baked), or placed by `to_world`, and supports_surface_sampling(); `material` is
    // emissive. Both must outlive the light.
    AreaLight(const Shape& shape, const Material& material, std::optional<Transform> to_world = std::nullopt);

    LightSample sample(const Vec3f& point, std::array<float, 2> u) const override;
    float pdf(const Vec3f& point, const Vec3f& direction, float distance, const Vec3f& light_normal) const override;
    // pi * area * (max channel of the front emission + max channel of the back emission), probed at one
    // surface point: a Lambertian one-sided emitter of radiance L emits pi * A * L.
    float power() const override { return power_; }

    const Shape& shape() const { return shape_; }
    const Material& material() const { return material_; }

private:
    const Shape& shape_;
    const Material& material_;
    // The light at `position` on the surface (front `normal`) seen from `point`, drawn with solid-angle density
    // pdf(distance², |cos_light|).
    template <class Pdf>
    LightSample towards(const Vec3f& point, const Vec3f& position, const Vec3f& normal, Pdf&& pdf) const;

    // A point of the shape in the world, with its density per world area.
    SurfaceSample sample_world(std::array<float, 2> u) const;
    // World area per own area where the world normal is `normal` (1 for a baked shape).
    double area_scale(const Vec3f& normal) const;
    // The density per world area of a point whose world normal is `normal`.
    float pdf_area(const Vec3f& normal) const;

    std::optional<Transform> to_world_;  // the placement of a shape in its own space
    float pdf_area_ = 0;  // 1 / the shape's own area
    bool by_solid_angle_ = false;  // the shape may sample by solid angle
    float power_ = 0;
};

}  // namespace isotrace
