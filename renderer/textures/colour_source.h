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

}  // namespace isotrace
