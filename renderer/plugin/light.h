#pragma once
#include <array>

#include "renderer/math/rgb.h"
#include "renderer/math/vec3.h"
#include "renderer/plugin/registry.h"

namespace isotrace {

// Incident light at a point from one light, for next-event estimation.
struct LightSample {
    Rgb radiance;          // for delta lights: the irradiance-like term that cos(theta) multiplies
    Vec3f direction;       // unit, from the shading point towards the light
    float distance = 0;    // to the light (infinity for distant lights)
    float pdf = 0;         // solid-angle pdf; 1 for delta lights
    bool is_delta = false;
};

class Light {
public:
    virtual ~Light() = default;
    virtual LightSample sample(const Vec3f& point, std::array<float, 2> u) const = 0;
    // Total emitted power (for light selection), in the working space's luminance-free max-channel sense.
    virtual float power() const = 0;
};

Registry<Light>& light_registry();

}  // namespace isotrace
