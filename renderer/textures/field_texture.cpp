#include "renderer/textures/field_texture.h"

#include <cmath>

#include "renderer/plugin/shape.h"

namespace isotrace {

float FieldTexture::evaluate(const TextureContext& context) const {
    if (!context.shape) return 0;
    const Vec3d point = context.shape_position - context.shape_normal * depth_;
    if (output_ == Output::Gradient) {
        const float gradient = float(length(context.shape->field_gradient(point)));
        return std::isfinite(gradient) ? gradient : 0.0f;
    }
    const float value = float(context.shape->field_value(point).value_or(0.0));
    return std::isfinite(value) ? value : 0.0f;
}

}  // namespace isotrace
