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

// A stratified grid of this many points per side estimates a placed shape's world area.
constexpr int kAreaProbesPerSide = 8;

AreaLight::AreaLight(const Shape& shape, const Material& material, std::optional<Transform> to_world)
    : shape_(shape), material_(material), to_world_(std::move(to_world)),
      by_solid_angle_(!to_world_ && shape.supports_solid_angle_sampling()) {
    if (!(shape.surface_area() > 0)) return;
    // Probe the emission on both sides of one surface point, looking straight at it.
    const SurfaceSample probe = sample_world({0.5f, 0.5f});
    pdf_area_ = shape.sample_surface({0.5f, 0.5f}).pdf_area;  // uniform by the shape's own area
    // The world area: the shape's own, times the mean area scale over a grid of its points.
    double area = shape.surface_area();
    if (to_world_) {
        double scale = 0;
        for (int i = 0; i < kAreaProbesPerSide; ++i)
            for (int j = 0; j < kAreaProbesPerSide; ++j)
                scale += area_scale(sample_world({(i + 0.5f) / kAreaProbesPerSide, (j + 0.5f) / kAreaProbesPerSide}).normal);
        area *= scale / (kAreaProbesPerSide * kAreaProbesPerSide);
    }
    const SurfaceHit hit = hit_at(probe.position, probe.normal, material, 0);
    const float front = material.emission(hit, probe.normal).max();
    const float back = material.emission(hit, -probe.normal).max();
    power_ = saturated_power(std::numbers::pi * area * (std::max(0.0, double(front)) + std::max(0.0, double(back))));
}

SurfaceSample AreaLight::sample_world(std::array<float, 2> u) const {
    SurfaceSample s = shape_.sample_surface(u);
    if (!to_world_) return s;
    s.position = to_world_->point(s.position);
    s.normal = safe_normalize(to_world_->normal(s.normal), s.normal);
    s.pdf_area = float(s.pdf_area / area_scale(s.normal));
    return s;
}

double AreaLight::area_scale(const Vec3f& normal) const {
    if (!to_world_) return 1;
    return std::abs(to_world_->determinant()) / length(to_world_->inverse_normal(Vec3d(normal)));
}

float AreaLight::pdf_area(const Vec3f& normal) const { return float(pdf_area_ / area_scale(normal)); }

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
    const SurfaceSample s = sample_world(u);
    if (!(s.pdf_area > 0)) return {};
    return towards(point, s.position, s.normal,
                   [&](float distance_squared, float cos_light) { return s.pdf_area * distance_squared / cos_light; });
}

float AreaLight::pdf(const Vec3f& point, const Vec3f& direction, float distance, const Vec3f& light_normal) const {
    if (by_solid_angle_)
        if (const float pdf = shape_.solid_angle_pdf(point); pdf > 0) return pdf;
    const float cos_light = std::abs(dot(light_normal, direction));
    const float density = pdf_area(light_normal);
    if (!(cos_light > 0) || !(density > 0)) return 0;
    const float pdf = density * (distance * distance) / cos_light;
    return std::isfinite(pdf) ? pdf : 0.0f;
}

}  // namespace isotrace
