#pragma once
// EnvironmentLight: radiance arriving from infinitely far away, either constant or from a lat-long
// (equirectangular) HDR image. Registered as light type "environment" (see environment_light.cpp).
//
// Map convention (map space; "transform" rotates map space into the world):
//   y is up; theta = angle from +y, phi around the y axis.
//   v = theta / pi: the image's top row is the +y pole, the bottom row the -y pole.
//   u = 0.5 + atan2(d.x, -d.z) / (2 pi): the image centre (u = 0.5) is -z (where the default camera looks),
//   u = 0.75 is +x, u = 0.25 is -x, the left/right edges (u = 0, 1) are +z. Seen from inside, the image is
//   not mirrored: +x lies to the right of -z.
//   Texel (x, y) covers u in [x, x+1) / width, v in [y, y+1) / height (y = 0 is the top row). Lookups are
//   bilinear between texel centres, wrapping around in u and clamped at the poles in v.
//
// Importance sampling (image maps): a Distribution2D over the texel cells with weight = integral over the cell
// of the bilinearly filtered luminance (a 3x3 blur with weights (1/8, 3/4, 1/8) per axis, so any cell the
// filter lets a non-zero texel reach has non-zero probability) times sin(theta) at the cell's centre.
// "Luminance" is the plain average of the RGB channels (negative channels count as 0). A uv sample with
// density pdf_uv has solid-angle density pdf_uv / (2 pi^2 sin theta). Constant environments are sampled
// uniformly over the sphere (pdf 1 / (4 pi)).
//
// power() = pi R^2 * max channel of the solid-angle average radiance, with R the radius of the bounding sphere
// of the scene bounds given to preprocess() (0 before it, or for an empty scene).
#include <memory>
#include <optional>

#include "renderer/math/transform.h"
#include "renderer/plugin/light.h"
#include "renderer/sampling/distribution_2d.h"
#include "renderer/textures/image_texture.h"

namespace isotrace {

class EnvironmentLight final : public Light {
public:
    // Constant radiance from every direction.
    explicit EnvironmentLight(const Rgb& radiance);
    // A lat-long map times `scale`; `to_world` takes map-space directions to the world. Its linear part must
    // be orthogonal (rotation, possibly with a reflection); translation is ignored. Throws
    // std::invalid_argument otherwise.
    EnvironmentLight(std::shared_ptr<const ImageTexture> map, float scale, const Transform& to_world = {});

    LightSample sample(const Vec3f& point, std::array<float, 2> u) const override;
    float pdf(const Vec3f& point, const Vec3f& direction, float distance, const Vec3f& light_normal) const override;
    Rgb escaped_radiance(const Vec3f& direction) const override;
    bool is_infinite() const override { return true; }
    float power() const override;
    void preprocess(const Bounds3f& scene_bounds) override;

    // The conventions above, in map space. direction_to_uv expects a unit vector.
    static std::array<float, 2> direction_to_uv(const Vec3f& map_direction);
    static Vec3f uv_to_direction(std::array<float, 2> uv);
    // Bilinear map value at map uv, times the scale (the constant radiance for constant environments).
    Rgb map_radiance(std::array<float, 2> uv) const;
    bool is_constant() const { return !map_; }

private:
    Vec3f to_map(const Vec3f& world_direction) const;
    Vec3f to_world(const Vec3f& map_direction) const;

    Rgb constant_;                              // constant environments
    std::shared_ptr<const ImageTexture> map_;   // image environments
    float scale_ = 1;
    std::optional<Distribution2D> distribution_;
    Rgb average_;                               // solid-angle average radiance (scaled)
    Transform to_world_, to_map_;
    bool rotated_ = false;
    float scene_radius_ = 0;
};

}  // namespace isotrace
