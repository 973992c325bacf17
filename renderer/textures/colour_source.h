#pragma once
// A colour-valued material parameter: a constant or an image texture (scaled), evaluated at a hit's uv.
#include <memory>

#include "renderer/math/rgb.h"
#include "renderer/scene/scene_node.h"
#include "renderer/scene/surface_hit.h"
#include "renderer/textures/image_texture.h"

namespace isotrace {

class ColourSource {
public:
    explicit ColourSource(const Rgb& constant) : scale_(constant) {}
    ColourSource(std::shared_ptr<const ImageTexture> texture, const Rgb& scale)
        : texture_(std::move(texture)), scale_(scale) {}

    Rgb evaluate(const SurfaceHit& hit) const { return texture_ ? texture_->lookup(hit.uv) * scale_ : scale_; }
    // evaluate() clamped to [0, 1]: a reflectance (textures may stray outside; energy must be conserved).
    Rgb evaluate_reflectance(const SurfaceHit& hit) const;
    bool is_constant() const { return !texture_; }
    // The constant value, or the scale of a texture.
    const Rgb& scale() const { return scale_; }

private:
    std::shared_ptr<const ImageTexture> texture_;
    Rgb scale_;
};

// Reads parent[key]: any colour form (see SceneNode::colour), or
// {"texture": "file.png", "space": "<OCIO colour space>" (optional), "scale": colour (optional, 1)}.
ColourSource parse_colour_source(const SceneNode& parent, const std::string& key, const Rgb& fallback);

// The same for a reflectance: a constant outside [0, 1] is an error at parent[key].
ColourSource parse_reflectance(const SceneNode& parent, const std::string& key, const Rgb& fallback);

}  // namespace isotrace
