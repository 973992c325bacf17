#pragma once
// The implicit field of the surface's shape as a scalar input: its value at the shading point moved `depth`
// inward along the normal (how deep inside the surface that point is, in the field's units), or the length of
// its gradient there. 0 where there is no shape (area-light samples).
#include "renderer/plugin/texture.h"

namespace isotrace {

class FieldTexture final : public ScalarTexture {
public:
    enum class Output { Value, Gradient };
    FieldTexture(Output output, double depth, const TextureNeeds& needs) : output_(output), depth_(depth), needs_(needs) {}

    float evaluate(const TextureContext& context) const override;
    TextureNeeds needs() const override { return needs_; }

private:
    Output output_;
    double depth_;
    TextureNeeds needs_;
};

}  // namespace isotrace
