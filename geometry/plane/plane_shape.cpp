#include "geometry/plane/plane_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/csg/inside_span_list.h"
#include "renderer/core/ray.h"
#include "renderer/params/world_limit.h"

namespace isotrace {

PlaneShape::PlaneShape(const Vec3d& point, const Vec3d& normal, double uv_scale)
    : FlatShape(frame_facing(point, normal, uv_scale)) {}

Bounds3f PlaneShape::bounds() const {
    // The half-space n·p ≤ n·origin within the world's cube (a solid's bounds hold its inside, for CSG). Per axis
    // k: n_k p_k ≤ n·origin − Σ_{j≠k} n_j p_j, whose right side is at most n·origin + kWorldLimit·Σ_{j≠k} |n_j| in
    // the cube. A half-space that misses the cube has empty bounds: nothing to hit.
    const Vec3d& n = frame().normal();
    const double offset = dot(n, frame().origin());
    Vec3d lower, upper;
    for (int k = 0; k < 3; ++k) {
        lower[k] = -kWorldLimit;
        upper[k] = kWorldLimit;
        const double limit = (offset + kWorldLimit * (std::abs(n[(k + 1) % 3]) + std::abs(n[(k + 2) % 3]))) / n[k];
        if (n[k] > 0) upper[k] = std::min(upper[k], limit);
        if (n[k] < 0) lower[k] = std::max(lower[k], limit);
        if (!(lower[k] <= upper[k])) return {};
    }
    Bounds3f box;
    box.extend(Vec3f(lower));
    box.extend(Vec3f(upper));
    return box;
}

LocalShading PlaneShape::shading(const RTCHit&, const Vec3f& geometric_normal, const Vec3d& point) const {
    const auto [s, t] = frame().coordinates(point);
    return {.geometric_normal = geometric_normal,
            .normal = geometric_normal,
            .uv = {float(s), float(t)},
            .dpdu = Vec3f(frame().axis_u()),
            .dpdv = Vec3f(frame().axis_v())};
}

void PlaneShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                              std::vector<InsideSpan>& spans, QueryScratch&) const {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const auto cut = [](double t) { return BoundaryPoint{t, {0, 0, 1}, BoundaryPoint::kCut, 0}; };
    const std::optional<double> t = frame().crossing(origin, direction);
    if (!t) {  // parallel: inside throughout when behind the plane
        if (frame().height(origin) < 0) append_clipped_span({cut(-kInfinity), cut(kInfinity)}, t_min, t_max, spans);
        return;
    }
    const BoundaryPoint surface{*t, frame().normal(), 0, 0};
    if (dot(frame().normal(), direction) > 0)  // leaving the half-space at t
        append_clipped_span({cut(-kInfinity), surface}, t_min, t_max, spans);
    else
        append_clipped_span({surface, cut(kInfinity)}, t_min, t_max, spans);
}

namespace {

std::unique_ptr<Shape> create(const SceneNode& node) {
    const Vec3d point = node.has("point") ? world_point(node, "point") : Vec3d{0, 0, 0};
    const Vec3d normal = node.has("normal") ? unit_direction(node, "normal") : Vec3d{0, 1, 0};
    const double uv_scale = node.number_or("uv_scale", 1.0, world_length());
    return std::make_unique<PlaneShape>(point, normal, uv_scale);
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "plane",
                         "infinite plane (CSG: the half-space behind it); point, normal, uv_scale", create)

}  // namespace isotrace
