#include "renderer/textures/colour_source.h"

#include <algorithm>

#include "renderer/colour/colour_system.h"

namespace isotrace {

Rgb ColourSource::evaluate_reflectance(const SurfaceHit& hit) const {
    const Rgb r = evaluate(hit);
    return {std::clamp(r.r, 0.0f, 1.0f), std::clamp(r.g, 0.0f, 1.0f), std::clamp(r.b, 0.0f, 1.0f)};
}

ColourSource parse_reflectance(const SceneNode& parent, const std::string& key, const Rgb& fallback) {
    ColourSource reflectance = parse_colour_source(parent, key, fallback);
    const Rgb r = reflectance.scale();
    if (reflectance.is_constant() && (r.r < 0 || r.g < 0 || r.b < 0 || r.max() > 1))
        parent.fail_at(key, "each reflectance component must lie in [0, 1] (energy conservation)");
    return reflectance;
}

ColourSource parse_colour_source(const SceneNode& parent, const std::string& key, const Rgb& fallback) {
    const auto value = parent.optional_value(key);
    if (!value) return ColourSource(fallback);
    if (!value->json().is_object() || !value->has("texture")) return ColourSource(value->as_colour());
    const std::filesystem::path file = value->file_path("texture");
    const std::string space = value->string_or("space", "");
    const Rgb scale = value->colour_or("scale", Rgb(1.0f));
    value->finish();
    try {
        return ColourSource(ImageTexture::load(file, space, *value->context().colours, *value->context().memory), scale);
    } catch (const InputError& error) {
        value->fail(error.what());
    }
}

}  // namespace isotrace
