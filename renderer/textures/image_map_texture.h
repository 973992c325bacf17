#pragma once
// An image looked up through a projection: trilinear filtering over the image's mip levels, whose level follows
// the footprint in texels, with the image's wrap mode. Rgb for colour and data images, float for one channel.
#include <memory>

#include "renderer/plugin/texture.h"
#include "renderer/textures/image_texture.h"
#include "renderer/textures/projection.h"

namespace isotrace {

template <class T>
class ImageMapTexture final : public Texture<T> {
public:
    static constexpr int kChannels = std::is_same_v<T, Rgb> ? 3 : 1;

    ImageMapTexture(std::shared_ptr<const ImageTexture> image, const Projection& projection, WrapMode wrap)
        : image_(std::move(image)), projection_(projection), wrap_(wrap) {}

    T evaluate(const TextureContext& context) const override {
        const ProjectedLookups lookups = projection_.project(context);
        const MipPyramid& pyramid = image_->pyramid();
        const float texels = std::max(lookups.footprint[0] * float(pyramid.width()),
                                      lookups.footprint[1] * float(pyramid.height()));
        const auto at = [&](const ProjectedPoint& p) {
            return value_of(pyramid.lookup<kChannels>({p.point.x, p.point.y}, texels, wrap_));
        };
        if (lookups.count == 1) return at(lookups.points[0]);
        T sum{};
        for (int i = 0; i < lookups.count; ++i) sum += at(lookups.points[std::size_t(i)]) * lookups.points[std::size_t(i)].weight;
        return sum;
    }
    TextureNeeds needs() const override { return projection_.needs(); }

private:
    static T value_of(const std::array<float, kChannels>& texel) {
        if constexpr (kChannels == 3)
            return ImageTexture::to_rgb(texel);
        else
            return texel[0];
    }

    std::shared_ptr<const ImageTexture> image_;
    Projection projection_;
    WrapMode wrap_;
};

}  // namespace isotrace
