#include "renderer/materials/emission_profile.h"

#include "renderer/params/emitted_colour.h"

namespace isotrace {

EmissionProfile parse_emission(const SceneNode& node, const std::string& radiance_key, bool required,
                               const std::string& two_sided_key, const std::string& scale_key) {
    EmissionProfile profile;
    profile.radiance = emitted_colour(node, radiance_key, required ? std::nullopt : std::optional<Rgb>(Rgb()),
                                      scale_key);
    profile.two_sided = node.boolean_or(two_sided_key, false);
    return profile;
}

}  // namespace isotrace
