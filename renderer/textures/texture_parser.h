#pragma once
// Material parameters that may be textures, read from a scene file. Every form is listed in docs/textures.md: a
// constant, an image, a pattern, an expression (mix, scale, offset, invert) or an input (field), nested up to
// kMaxTextureDepth levels.
#include <string>

#include "renderer/math/rgb.h"
#include "renderer/params/scene_node.h"
#include "renderer/plugin/texture.h"

namespace isotrace {

// How deeply texture nodes may nest: the parser recurses once per level.
constexpr int kMaxTextureDepth = 32;

// parent[key] as a texture of that kind; absent: the constant fallback. Constants are checked against `range`
// (file:line:column, JSON path, exit 2); varying textures are clamped to it when evaluated.
ScalarTexturePtr parse_scalar_texture(const SceneNode& parent, const std::string& key, float fallback,
                                      NumberRange range);

enum class ColourRange {
    Any,
    Reflectance,  // each component in [0, 1]
    Emission      // each component in [0, kMaxEmitted] (renderer/params/emitted_colour.h)
};
ColourTexturePtr parse_colour_texture(const SceneNode& parent, const std::string& key, const Rgb& fallback,
                                      ColourRange range);

// Like parse_colour_texture, but images are data (no colour conversion; for normal maps), values as stored.
// Absent: null (the material has no such map).
ColourTexturePtr parse_data_texture(const SceneNode& parent, const std::string& key);

}  // namespace isotrace
