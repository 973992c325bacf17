#include "geometry/sphere/sphere_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/csg/inside_span_list.h"
#include "geometry/csg/span_combination.h"
#include "geometry/sphere/sphere_intersection.h"
#include "renderer/core/ray.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

// The nearest root strictly inside (t_near, t_far), if any.
std::optional<double> nearest_root(const SphereRoots& roots, double t_near, double t_far) {
    if (roots.t0 > t_near && roots.t0 < t_far) return roots.t0;
    if (roots.t1 > t_near && roots.t1 < t_far) return roots.t1;
    return std::nullopt;
}

// The nearest root of sphere `s` in (t_near, t_far), if any.
std::optional<double> first_hit(const Sphere& s, const Vec3d& origin, const Vec3d& direction, double t_near,
                                float t_far) {
    const auto roots = intersect_sphere(origin, direction, s.centre, s.radius);
    if (!roots) return std::nullopt;
    return nearest_root(*roots, t_near, t_far);
}

}  // namespace

SphereShape::SphereShape(std::vector<Sphere> spheres) : spheres_(std::move(spheres)) { build_area_distribution(); }

void SphereShape::build_area_distribution() {
    std::vector<double> areas;
    areas.reserve(spheres_.size());
    for (const Sphere& s : spheres_) areas.push_back(4 * std::numbers::pi * s.radius * s.radius);
    areas_ = AreaDistribution(areas);
}

SurfaceSample SphereShape::sample_surface(std::array<float, 2> u) const {
    if (!(areas_.total() > 0)) return {};
    const AreaDistribution::Pick pick = areas_.pick(u[0]);
    const Sphere& s = spheres_[pick.index];
    const Vec3f direction = square_to_uniform_sphere({pick.reused_u, u[1]});
    SurfaceSample sample;
    sample.position = Vec3f(s.centre + Vec3d(direction) * s.radius);
    sample.normal = direction;
    sample.pdf_area = float(1.0 / areas_.total());
    return sample;
}

Bounds3f SphereShape::bounds() const {
    Bounds3f b;
    for (const Sphere& s : spheres_) {
        b.extend(Vec3f(s.centre - Vec3d(s.radius, s.radius, s.radius)));
        b.extend(Vec3f(s.centre + Vec3d(s.radius, s.radius, s.radius)));
    }
    return b;
}

void SphereShape::bake(const Transform& to_world) {
    const double scale = to_world.similarity_scale();
    for (Sphere& s : spheres_) {
        s.centre = to_world.point(s.centre);
        s.radius *= scale;
    }
    build_area_distribution();
}

RTCGeometry SphereShape::create_geometry(RTCDevice device) {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    return user_geometry::create<bounds_callback>(device, this, unsigned(spheres_.size()), intersect_callback,
                                                  occluded_callback);
}

void SphereShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const SphereShape*>(args->geometryUserPtr);
    const Sphere& s = self->spheres_[args->primID];
    const Vec3d extent(s.radius, s.radius, s.radius);
    user_geometry::store_bounds(args->bounds_o, s.centre - extent, s.centre + extent);
}

void SphereShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const SphereShape*>(args->geometryUserPtr);
    const Sphere& s = self->spheres_[args->primID];
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
            return first_hit(s, origin, direction, t_near, t_far);
        },
        [&](unsigned i, const Vec3d& origin, const Vec3d& direction, double t) {
            user_geometry::store_hit(args, i, float(t), origin + direction * t - s.centre);  // uv: see shading()
        });
}

void SphereShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const SphereShape*>(args->geometryUserPtr);
    const Sphere& s = self->spheres_[args->primID];
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    return first_hit(s, origin, direction, t_near, t_far);
                                });
}

std::optional<InsideSpan> SphereShape::span_of(std::uint32_t index, const Vec3d& origin, const Vec3d& direction) const {
    const Sphere& s = spheres_[index];
    const auto roots = intersect_sphere(origin, direction, s.centre, s.radius);
    if (!roots || !(roots->t0 < roots->t1)) return std::nullopt;  // a tangent line touches without entering
    const auto end = [&](double t) { return BoundaryPoint{t, normalize(origin + direction * t - s.centre), index, 0}; };
    return InsideSpan{end(roots->t0), end(roots->t1)};
}

void SphereShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                               std::vector<InsideSpan>& spans, QueryScratch&) const {
    if (spheres_.size() == 1) {
        if (const auto span = span_of(0, origin, direction)) append_clipped_span(*span, t_min, t_max, spans);
        return;
    }
    std::vector<SpanEvent> events;
    std::vector<InsideSpan> clipped;
    for (std::uint32_t k = 0; k < spheres_.size(); ++k) {
        clipped.clear();
        if (const auto span = span_of(k, origin, direction)) append_clipped_span(*span, t_min, t_max, clipped);
        append_span_events(k, 0, clipped, events);
    }
    combine_span_events(CsgOperation::Union, std::uint32_t(spheres_.size()), events, spans);
}

LocalShading SphereShape::shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d&) const {
    // Spherical coordinates of the normal, y up: u around the axis, v from the top (0) to the bottom (1).
    const Vec3f& n = geometric_normal;
    const float u = 0.5f + std::atan2(n.x, n.z) * float(0.5 * std::numbers::inv_pi);
    const float v = std::acos(std::clamp(n.y, -1.0f, 1.0f)) * float(std::numbers::inv_pi);
    // p = c + r·(sin θ sin φ, cos θ, sin θ cos φ) with φ = 2π(u − ½), θ = πv. At the poles (sin θ = 0) φ is the
    // one u names (atan2(0, 0) = 0), so dpdv still points along the meridian and dpdu is zero there.
    const float radius = float(spheres_[hit.primID].radius);
    const float sin_theta = std::sqrt(n.x * n.x + n.z * n.z);
    const float sin_phi = sin_theta > 0 ? n.x / sin_theta : 0.0f, cos_phi = sin_theta > 0 ? n.z / sin_theta : 1.0f;
    const float two_pi_r = float(2 * std::numbers::pi) * radius, pi_r = float(std::numbers::pi) * radius;
    return {.geometric_normal = n,
            .normal = n,
            .uv = {u, v},
            .dpdu = Vec3f(n.z, 0, -n.x) * two_pi_r,
            .dpdv = Vec3f(n.y * sin_phi, -sin_theta, n.y * cos_phi) * pi_r};
}

namespace {

Sphere parse_sphere(const SceneNode& node) {
    Sphere s;
    s.centre = node.vec3_or("center", {0, 0, 0});
    s.radius = node.number_or("radius", 1.0, NumberRange::positive());
    if (max_component(abs(s.centre)) + s.radius > kWorldLimit)  // Embree silently drops bounds this large
        node.fail("sphere extends beyond 1e18 from the origin");
    return s;
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    std::vector<Sphere> spheres;
    const std::vector<SceneNode> list = node.object_array("spheres");
    if (!list.empty() && (node.has("center") || node.has("radius")))
        node.fail("give either \"center\"/\"radius\" or a \"spheres\" list, not both");
    for (const SceneNode& item : list) {
        spheres.push_back(parse_sphere(item));
        item.finish();
    }
    if (list.empty()) {
        if (node.has("spheres")) node.fail_at("spheres", "the list of spheres is empty");
        spheres.push_back(parse_sphere(node));
    }
    return std::make_unique<SphereShape>(std::move(spheres));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "sphere", "analytic sphere(s); center, radius or spheres: [{center, radius}]",
                         create)

bool SphereShape::certainly_outside(const Vec3d& point, double distance) const {
    constexpr double kRounding = 1e-12;  // of the distance to the centre, relative to the radius
    return std::all_of(spheres_.begin(), spheres_.end(), [&](const Sphere& s) {
        return length(point - s.centre) - s.radius > distance + kRounding * s.radius;
    });
}

}  // namespace isotrace
