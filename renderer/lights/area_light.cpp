#include "renderer/lights/area_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/params/emitted_colour.h"
#include "renderer/plugin/surface_hit.h"

namespace isotrace {
namespace {

SurfaceHit hit_at(const Vec3f& position, const Vec3f& normal, const Material& material, float t) {
    SurfaceHit hit;
    hit.t = t;
    hit.position = position;
    hit.geometric_normal = normal;
    hit.shading_normal = normal;
    hit.material = &material;
    return hit;
}

}  // namespace

AreaLight::AreaLight(const Shape& shape, const Material& material)
    : shape_(shape), material_(material), by_solid_angle_(shape.supports_solid_angle_sampling()) {
    if (!(shape.surface_area() > 0)) return;
    // Probe the emission on both sides of one surface point, looking straight at it.
    const SurfaceSample probe = shape.sample_surface({0.5f, 0.5f});
    pdf_area_ = probe.pdf_area;  // uniform by area: the same everywhere
    const float area = shape.surface_area();
    const SurfaceHit hit = hit_at(probe.position, probe.normal, material, 0);
    const float front = material.emission(hit, probe.normal).max();
    const float back = material.emission(hit, -probe.normal).max();
    power_ = saturated_power(std::numbers::pi * area * (std::max(0.0, double(front)) + std::max(0.0, double(back))));
}

template <class Pdf>
LightSample AreaLight::towards(const Vec3f& point, const Vec3f& position, const Vec3f& normal, Pdf&& pdf) const {
    const Vec3f offset = position - point;
    const float distance_squared = dot(offset, offset);
    if (!(distance_squared > 0)) return {};
    const float distance = std::sqrt(distance_squared);
    const Vec3f direction = offset / distance;
    const float cos_light = std::abs(dot(normal, direction));
    if (!(cos_light > 0)) return {};
    LightSample result;
    result.direction = direction;
    result.distance = distance;
    result.pdf = pdf(distance_squared, cos_light);
    if (!std::isfinite(result.pdf)) return {};
    result.radiance = material_.emission(hit_at(position, normal, material_, distance), -direction);
    return result;
}

LightSample AreaLight::sample(const Vec3f& point, std::array<float, 2> u) const {
    if (by_solid_angle_) {
        const SolidAngleSample s = shape_.sample_solid_angle(point, u);
        if (s.pdf_solid_angle > 0) return towards(point, s.position, s.normal, [&](float, float) { return s.pdf_solid_angle; });
    }
    const SurfaceSample s = shape_.sample_surface(u);
    if (!(s.pdf_area > 0)) return {};
    return towards(point, s.position, s.normal,
                   [&](float distance_squared, float cos_light) { return s.pdf_area * distance_squared / cos_light; });
}

float AreaLight::pdf(const Vec3f& point, const Vec3f& direction, float distance, const Vec3f& light_normal) const {
    if (by_solid_angle_)
        if (const float pdf = shape_.solid_angle_pdf(point); pdf > 0) return pdf;
    const float cos_light = std::abs(dot(light_normal, direction));
    if (!(cos_light > 0) || !(pdf_area_ > 0)) return 0;
    const float pdf = pdf_area_ * (distance * distance) / cos_light;
    return std::isfinite(pdf) ? pdf : 0.0f;
}

}  // namespace isotrace
