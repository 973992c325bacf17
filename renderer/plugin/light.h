#pragma once
// Light: a source that next-event estimation can sample. Registered types (point, directional, environment)
// come from the scene's "lights"; area lights are made by the scene for emissive objects whose shape can be
// sampled (see renderer/lights/area_light.h).
#include <array>
#include <optional>

#include "renderer/math/rgb.h"
#include "renderer/math/vec3.h"
#include "renderer/plugin/registry.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

// Incident light at a point from one light.
// Each vector shares 16 bytes with the float read next to it, so that a light can store each pair at once and the
// caller's loads of them, across the virtual call, find each in one store (a load spanning two stores waits for
// them; docs/decisions.md, "Hot data is written the way it is read").
struct LightSample {
    Vec3f direction;       // unit, from the shading point towards the light
    float distance = 0;    // to the sampled point (infinity for infinite lights)
    Rgb radiance;          // incident radiance (delta lights: the irradiance-like term that cos(theta) multiplies)
    float pdf = 0;         // solid-angle pdf at the shading point; 1 for delta lights; 0 = no sample
    bool is_delta = false;
};

class Light {
public:
    virtual ~Light() = default;

    virtual LightSample sample(const Vec3f& point, std::array<float, 2> u) const = 0;

    // Solid-angle pdf with which sample(point, ...) returns `direction`, where a ray from `point` along it hits
    // this light at `distance` with geometric normal `light_normal` (both ignored by infinite lights).
    // Used to weight hits found by BSDF sampling (multiple importance sampling). 0 for delta lights.
    virtual float pdf(const Vec3f& point, const Vec3f& direction, float distance, const Vec3f& light_normal) const {
        (void)point, (void)direction, (void)distance, (void)light_normal;
        return 0;
    }

    // Infinite lights: radiance arriving along a ray that leaves the scene in `direction`.
    virtual Rgb escaped_radiance(const Vec3f& direction) const {
        (void)direction;
        return {};
    }
    virtual bool is_infinite() const { return false; }
    // A point or a direction (point, spot, directional): sample() returns the same for every u.
    virtual bool is_delta() const { return false; }

    // Emitted power (max over channels), for choosing lights in proportion to it. Lights at infinity need the
    // scene's extent, given to preprocess() after the scene is built.
    virtual float power() const = 0;
    virtual void preprocess(const Bounds3f& scene_bounds) { (void)scene_bounds; }
};

Registry<Light>& light_registry();

}  // namespace isotrace
