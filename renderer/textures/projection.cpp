#include "renderer/textures/projection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/core/did_you_mean.h"
#include "renderer/params/scene_node.h"
#include "renderer/params/transform_parser.h"

namespace isotrace {
namespace {

constexpr float kTwoPi = 2 * std::numbers::pi_v<float>;
constexpr float kPi = std::numbers::pi_v<float>;

}  // namespace

Projection::Projection(const ProjectionSettings& settings, const TextureNeeds& uv_need)
    : kind_(settings.kind),
      axis_(settings.axis),
      sharpness_(settings.sharpness),
      object_space_(settings.object_space),
      placed_(!settings.placement.is_identity()),
      placement_(settings.placement),
      footprint_scale_(float(std::cbrt(1 / std::abs(settings.placement.determinant())))),
      needs_(settings.kind == ProjectionKind::Uv ? uv_need : TextureNeeds{}) {
    needs_.uv = settings.kind == ProjectionKind::Uv;
}

ProjectedLookups Projection::project(const TextureContext& context) const {
    ProjectedLookups result;
    if (kind_ == ProjectionKind::Uv) {
        const Vec3f placed = to_texture_point({context.uv[0], context.uv[1], 0});
        result.points[0].point = {placed.x, placed.y, 0};
        // The footprint along u is the world footprint over the surface's stretch along u.
        if (context.footprint > 0) {
            const float du = length(context.dpdu), dv = length(context.dpdv);
            result.footprint = {du > 0 ? context.footprint / du * footprint_scale_ : 0,
                                dv > 0 ? context.footprint / dv * footprint_scale_ : 0};
        }
        return result;
    }
    const Vec3f p = to_texture_point(object_space_ ? context.object_position : context.position);
    const float footprint = (object_space_ ? context.object_footprint : context.footprint) * footprint_scale_;
    result.footprint = {footprint, footprint};
    switch (kind_) {
        case ProjectionKind::Solid:
            result.points[0].point = p;
            break;
        case ProjectionKind::Planar: {
            const auto [u, v] = planar(p, axis_);
            result.points[0].point = {u, v, 0};
            break;
        }
        case ProjectionKind::Triplanar: {
            Vec3f n = object_space_ ? context.object_normal : context.normal;
            if (placed_) n = Vec3f(placement_.inverse_normal(Vec3d(n)));  // the normal transform of the inverse
            std::array<float, 3> w;
            float sum = 0;
            for (int axis = 0; axis < 3; ++axis) sum += w[std::size_t(axis)] = std::pow(std::abs(n[axis]), sharpness_);
            result.count = 3;
            for (int axis = 0; axis < 3; ++axis) {
                const auto [u, v] = planar(p, axis);
                result.points[std::size_t(axis)] = {{u, v, 0}, sum > 0 ? w[std::size_t(axis)] / sum : 1.0f / 3};
            }
            break;
        }
        case ProjectionKind::Spherical:
        case ProjectionKind::Cylindrical: {
            const float a = p[(axis_ + 1) % 3], b = p[(axis_ + 2) % 3], h = p[axis_];
            const float around = std::sqrt(a * a + b * b);  // distance from the axis
            const float u = 0.5f + std::atan2(b, a) / kTwoPi;
            result.footprint[0] = around > 0 ? footprint / (kTwoPi * around) : 0;
            if (kind_ == ProjectionKind::Cylindrical) {
                result.points[0].point = {u, h, 0};
            } else {
                const float r = std::sqrt(around * around + h * h);
                const float v = r > 0 ? 0.5f + std::asin(std::clamp(h / r, -1.0f, 1.0f)) / kPi : 0.5f;
                result.points[0].point = {u, v, 0};
                result.footprint[1] = r > 0 ? footprint / (kPi * r) : 0;
            }
            break;
        }
        case ProjectionKind::Uv:
            break;
    }
    return result;
}

Projection parse_projection(const SceneNode& parent, const std::string& key, ProjectionKind fallback) {
    static const std::vector<std::string> kinds{"uv", "solid", "planar", "triplanar", "spherical", "cylindrical"};
    const auto value = parent.optional_value(key);
    if (!value) return Projection({.kind = fallback}, {.uv = true, .where = parent.location(), .field_path = parent.path()});
    const auto kind_of = [&](const SceneNode& node, const std::string& name) {
        const auto found = std::find(kinds.begin(), kinds.end(), name);
        if (found == kinds.end()) {
            std::string list;
            for (const auto& k : kinds) list += (list.empty() ? "" : ", ") + k;
            node.fail("unknown projection \"" + name + "\"" + did_you_mean(name, kinds) + "; expected one of: " + list);
        }
        return ProjectionKind(found - kinds.begin());
    };
    const TextureNeeds uv_need{.uv = true, .where = value->location(), .field_path = value->path()};
    if (value->json().is_string()) return Projection({.kind = kind_of(*value, value->json().string)}, uv_need);
    if (!value->json().is_object())
        value->fail("expected a projection: \"uv\", \"solid\", ... or {\"type\": ...}");
    ProjectionSettings settings;
    const std::string type = value->string("type");
    settings.kind = kind_of(*value->optional_value("type"), type);
    if (settings.kind == ProjectionKind::Planar || settings.kind == ProjectionKind::Spherical ||
        settings.kind == ProjectionKind::Cylindrical) {
        const std::string axis = value->choice_or("axis", settings.kind == ProjectionKind::Planar ? "z" : "y", {"x", "y", "z"});
        settings.axis = axis[0] - 'x';
    }
    if (settings.kind == ProjectionKind::Triplanar)
        settings.sharpness = float(value->number_or("sharpness", 4, NumberRange::between(1, 64)));
    if (settings.kind != ProjectionKind::Uv)
        settings.object_space = value->choice_or("space", "object", {"object", "world"}) == "object";
    settings.placement = parse_optional_transform(*value, "transform");
    value->finish();
    return Projection(settings, uv_need);
}

}  // namespace isotrace
