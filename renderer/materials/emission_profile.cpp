#include "renderer/materials/emission_profile.h"

namespace isotrace {

EmissionProfile parse_emission(const SceneNode& node, const std::string& radiance_key, bool required,
                               const std::string& two_sided_key) {
    EmissionProfile profile;
    profile.radiance = required ? node.colour(radiance_key) : node.colour_or(radiance_key, Rgb());
    if (profile.radiance.r < 0 || profile.radiance.g < 0 || profile.radiance.b < 0)
        node.fail_at(radiance_key, "emitted radiance must not be negative");
    profile.two_sided = node.boolean_or(two_sided_key, false);
    return profile;
}

}  // namespace isotrace
