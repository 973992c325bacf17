#pragma once
// Emitted quantities as scenes give them (a light's intensity, irradiance or radiance, a surface's emission, a
// preview sky): a colour times an optional scale, each channel in [0, kMaxEmitted]. Light is multiplied by areas,
// solid angles, squared scene radii and path weights in float, whose range ends at 3.4e38: 1e30 leaves those
// products room, where 1e38 made the lights' distributions overflow.
#include <optional>
#include <string>

#include "renderer/math/rgb.h"
#include "renderer/params/scene_node.h"

namespace isotrace {

inline constexpr double kMaxEmitted = 1e30;

// node[colour_key] (`fallback` when absent; required when there is none) times node[scale_key] (1 when absent;
// no scale when the key is empty), the product formed in double. Fails at the colour's position when a channel
// is negative or beyond the limit, at the scale's when the product is.
Rgb emitted_colour(const SceneNode& node, const std::string& colour_key, std::optional<Rgb> fallback,
                   const std::string& scale_key = "");

// A power (watts, for choosing lights in proportion to it) formed in double: lights at infinity multiply their
// radiance by the squared radius of the scene, which float cannot always hold. Saturates at float's largest value,
// where only the choice among such lights flattens.
float saturated_power(double power);

}  // namespace isotrace
