// Environment light: constant or lat-long HDR image radiance from infinitely far away. Conventions and the
// sampling density are documented in environment_light.h.
#include "renderer/lights/environment_light.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "renderer/colour/colour_system.h"
#include "renderer/core/input_error.h"
#include "renderer/params/emitted_colour.h"
#include "renderer/params/transform_parser.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// a + (b - a) t: exactly a where a = b (constant regions and the clamped poles stay exact).
Rgb lerp(const Rgb& a, const Rgb& b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

float luminance(const Rgb& c) { return (std::max(0.0f, c.r) + std::max(0.0f, c.g) + std::max(0.0f, c.b)) / 3.0f; }

}  // namespace

EnvironmentLight::EnvironmentLight(const Rgb& radiance) : constant_(radiance), average_(radiance) {}

EnvironmentLight::EnvironmentLight(std::shared_ptr<const ImageTexture> map, float scale, const Transform& to_world)
    : map_(std::move(map)), scale_(scale), to_world_(to_world), to_map_(to_world.inverse()),
      rotated_(!to_world.is_identity()) {
    if (!map_) throw std::invalid_argument("EnvironmentLight: no map");
    if (std::abs(to_world.similarity_scale(1e-6) - 1.0) > 1e-6)
        throw std::invalid_argument("the transform of an environment must be a rotation");
    const int width = map_->width(), height = map_->height();
    std::vector<float> lum(std::size_t(width) * std::size_t(height));
    float brightest = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Rgb texel = map_->texel(x, y);
            brightest = std::max(brightest, texel.max());
            lum[std::size_t(y) * std::size_t(width) + std::size_t(x)] = luminance(texel);
        }
    // The map's own values are summed in float for its distribution, and the scale multiplies every lookup.
    if (!(brightest <= kMaxEmitted) || !(double(brightest) * scale_ <= kMaxEmitted)) {
        char values[64];
        std::snprintf(values, sizeof values, "(%.3g) times the scale (%.3g)", double(brightest), double(scale_));
        throw std::invalid_argument(std::string("the map's brightest texel ") + values +
                                    " exceeds the supported maximum radiance of 1e30");
    }
    const auto lum_at = [&](int x, int y) {  // wrapping in x, clamped in y (as the bilinear lookup)
        x = (x % width + width) % width;
        y = std::clamp(y, 0, height - 1);
        return lum[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    };
    // Integral of the bilinear reconstruction over a cell: 1-D tent weights (1/8, 3/4, 1/8) per axis.
    constexpr float kernel[3] = {0.125f, 0.75f, 0.125f};
    std::vector<float> weights(lum.size());
    double solid_angle_sum = 0;
    Rgb average_sum;
    for (int y = 0; y < height; ++y) {
        const float sin_theta = std::sin(kPi * (float(y) + 0.5f) / float(height));
        const double band = std::cos(std::numbers::pi * y / height) - std::cos(std::numbers::pi * (y + 1) / height);
        for (int x = 0; x < width; ++x) {
            float sum = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) sum += kernel[dy + 1] * kernel[dx + 1] * lum_at(x + dx, y + dy);
            weights[std::size_t(y) * std::size_t(width) + std::size_t(x)] = sum * sin_theta;
            average_sum += map_->texel(x, y) * float(band);
            solid_angle_sum += band;
        }
    }
    distribution_.emplace(weights, std::size_t(width), std::size_t(height));
    average_ = average_sum * float(scale_ / solid_angle_sum);
}

std::array<float, 2> EnvironmentLight::direction_to_uv(const Vec3f& d) {
    const float u = 0.5f + std::atan2(d.x, -d.z) * (0.5f / kPi);
    const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
    return {std::clamp(u, 0.0f, kOneMinusEpsilon), std::clamp(v, 0.0f, 1.0f)};
}

Vec3f EnvironmentLight::uv_to_direction(std::array<float, 2> uv) {
    const float theta = kPi * uv[1];
    const float phi = 2 * kPi * (uv[0] - 0.5f);
    const float sin_theta = std::sin(theta);
    return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

Vec3f EnvironmentLight::to_map(const Vec3f& d) const { return rotated_ ? normalize(to_map_.vector(d)) : d; }
Vec3f EnvironmentLight::to_world(const Vec3f& d) const { return rotated_ ? normalize(to_world_.vector(d)) : d; }

Rgb EnvironmentLight::map_radiance(std::array<float, 2> uv) const {
    if (!map_) return constant_;
    const int width = map_->width(), height = map_->height();
    const float x = uv[0] * float(width) - 0.5f;
    const float y = uv[1] * float(height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    const int x0 = int(fx), y0 = int(fy);  // texel() wraps x
    const int ya = std::clamp(y0, 0, height - 1), yb = std::clamp(y0 + 1, 0, height - 1);
    const Rgb top = lerp(map_->texel(x0, ya), map_->texel(x0 + 1, ya), tx);
    const Rgb bottom = lerp(map_->texel(x0, yb), map_->texel(x0 + 1, yb), tx);
    return lerp(top, bottom, ty) * scale_;
}

Rgb EnvironmentLight::escaped_radiance(const Vec3f& direction) const {
    if (!map_) return constant_;
    if (!is_finite(direction)) return {};  // an untraceable ray's (RenderScene::intersect): it has no place on the map
    return map_radiance(direction_to_uv(to_map(normalize(direction))));
}

LightSample EnvironmentLight::sample(const Vec3f&, std::array<float, 2> u) const {
    LightSample result;
    result.distance = std::numeric_limits<float>::infinity();
    if (!map_) {
        result.direction = square_to_uniform_sphere(u);
        result.pdf = square_to_uniform_sphere_pdf();
        result.radiance = constant_;
        return result;
    }
    const Distribution2D::Sample s = distribution_->sample(u);
    const float sin_theta = std::sin(kPi * s.uv[1]);
    if (!(sin_theta > 0) || !(s.pdf > 0)) return {};
    result.direction = to_world(uv_to_direction(s.uv));
    result.pdf = s.pdf / (2 * kPi * kPi * sin_theta);
    result.radiance = map_radiance(s.uv);
    return result;
}

float EnvironmentLight::pdf(const Vec3f&, const Vec3f& direction, float, const Vec3f&) const {
    if (!map_) return square_to_uniform_sphere_pdf();
    const Vec3f d = to_map(normalize(direction));
    const float sin_theta = std::sqrt(d.x * d.x + d.z * d.z);
    if (!(sin_theta > 0)) return 0;
    return distribution_->pdf(direction_to_uv(d)) / (2 * kPi * kPi * sin_theta);
}

float EnvironmentLight::power() const {
    return saturated_power(std::numbers::pi * double(scene_radius_) * scene_radius_ * average_.max());
}

void EnvironmentLight::preprocess(const Bounds3f& scene_bounds) {
    scene_radius_ = scene_bounds.bounding_radius();
}

namespace {

// The sampling distribution built from a map (measured; docs/reliability.md): per texel the luminance and the
// weights (floats, freed after the build), and the row's Distribution1D (weight, CDF double, guide index); per row
// its Distribution1D object, their allocations and the marginal's entries.
constexpr TextureSetUpMemory kSamplingSetUpMemory{
    2 * sizeof(float) + sizeof(float) + sizeof(double) + sizeof(std::size_t), 256};

std::unique_ptr<Light> create(const SceneNode& node) {
    if (!node.has("file")) {
        if (node.has("space"))
            node.fail_at("space", "\"space\" applies to \"file\" maps; give the colour's space in \"radiance\"");
        if (node.has("transform")) node.fail_at("transform", "a constant environment has no transform");
        return std::make_unique<EnvironmentLight>(emitted_colour(node, "radiance", Rgb(1.0f), "scale"));
    }
    if (node.has("radiance")) node.fail("give either \"radiance\" or \"file\", not both");
    const std::filesystem::path file = node.file_path("file");
    const std::string space = node.string_or("space", "");
    const float scale = float(node.number_or("scale", 1.0, NumberRange::non_negative()));
    const Transform to_world = parse_optional_transform(node, "transform");
    if (std::abs(to_world.similarity_scale(1e-6) - 1.0) > 1e-6)
        node.fail_at("transform", "the transform of an environment must be a rotation");
    if (!node.context().colours) node.fail("no colour system available to read \"" + file.string() + "\"");
    std::shared_ptr<const ImageTexture> map;
    try {
        map = ImageTexture::load(file, space, *node.context().colours, *node.context().memory,
                                  {.set_up = kSamplingSetUpMemory});
    } catch (const InputError& error) {
        node.fail_at("file", error.what());
    }
    return at_node(*node.optional_value("file"),
                   [&] { return std::make_unique<EnvironmentLight>(std::move(map), scale, to_world); });
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(light_registry, "environment",
                         "light from infinitely far away; radiance (colour) or file (lat-long HDR image, +y up, "
                         "top row = +y, centre = -z), space, transform (rotation); scale",
                         create)

}  // namespace isotrace
