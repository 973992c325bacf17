#pragma once
// A texture's value at a hit. A constant answers without a TextureContext: materials evaluate their parameters at
// every hit, and most parameters are constants.
#include "renderer/plugin/texture.h"

namespace isotrace {

template <class T>
T texture_at_hit(const Texture<T>& texture, const SurfaceHit& hit) {
    if (const std::optional<T> value = texture.constant()) return *value;
    return texture.evaluate(TextureContext(hit));
}

}  // namespace isotrace
