#include "renderer/textures/colour_source.h"

#include "renderer/colour/colour_system.h"

namespace isotrace {

ColourSource parse_colour_source(const SceneNode& parent, const std::string& key, const Rgb& fallback) {
    const auto value = parent.optional_value(key);
    if (!value) return ColourSource(fallback);
    if (!value->json().is_object() || !value->has("texture")) return ColourSource(value->as_colour());
    const std::filesystem::path file = value->file_path("texture");
    const std::string space = value->string_or("space", "");
    const Rgb scale = value->colour_or("scale", Rgb(1.0f));
    value->finish();
    try {
        return ColourSource(ImageTexture::load(file, space, *value->context().colours), scale);
    } catch (const InputError& error) {
        value->fail(error.what());
    }
}

}  // namespace isotrace
