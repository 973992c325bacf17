#include "geometry/cone/frustum_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/csg/inside_span_list.h"
#include "renderer/core/ray.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// The first crossing strictly inside (t_near, t_far).
std::optional<FrustumCrossing> first_hit(const Frustum& f, const Vec3d& origin, const Vec3d& direction, double t_near,
                                         double t_far) {
    const FrustumCrossings crossings = frustum_crossings(f, origin, direction);
    for (int i = 0; i < crossings.count; ++i)
        if (crossings.crossing[i].t > t_near && crossings.crossing[i].t < t_far) return crossings.crossing[i];
    return std::nullopt;
}

}  // namespace

FrustumShape::FrustumShape(std::string type, const Frustum& frustum) : type_(std::move(type)), frustum_(frustum) {
    build_area_distribution();
}

void FrustumShape::build_area_distribution() {
    const Frustum& f = frustum_;
    const double slant = std::hypot(f.height, f.top_radius - f.base_radius);
    const double cap = f.caps ? 1.0 : 0.0;
    const double areas[] = {std::numbers::pi * (f.base_radius + f.top_radius) * slant,
                            cap * std::numbers::pi * f.base_radius * f.base_radius,
                            cap * std::numbers::pi * f.top_radius * f.top_radius};
    areas_ = AreaDistribution(areas);
}

SurfaceSample FrustumShape::sample_surface(std::array<float, 2> u) const {
    if (!(areas_.total() > 0)) return {};
    const Frustum& f = frustum_;
    const AreaDistribution::Pick pick = areas_.pick(u[0]);
    const double w = pick.reused_u;
    Vec3d local, normal;
    if (pick.index == std::size_t(FrustumPart::Side)) {
        // The side's area grows with the radius: R(v)² is uniform between the rims' squared radii, and
        // v = (R − r₀)/(r₁ − r₀) is written without that difference, which vanishes for a cylinder.
        const double r0 = f.base_radius, r1 = f.top_radius;
        const double radius = std::sqrt(r0 * r0 + w * (r1 * r1 - r0 * r0));
        const double v = radius + r0 > 0 ? w * (r0 + r1) / (radius + r0) : 0;
        const double phi = kTwoPi * u[1];
        local = {radius * std::cos(phi), radius * std::sin(phi), v * f.height};
        normal = normalize(Vec3d(std::cos(phi), std::sin(phi), -f.slope()));
    } else {
        const bool top = pick.index == std::size_t(FrustumPart::Top);
        const double radius = top ? f.top_radius : f.base_radius;
        const std::array<float, 2> disk = square_to_uniform_disk_concentric({float(w), u[1]});
        local = {disk[0] * radius, disk[1] * radius, top ? f.height : 0};
        normal = {0, 0, top ? 1.0 : -1.0};
    }
    SurfaceSample sample;
    sample.position = Vec3f(f.origin + f.world_vector(local));
    sample.normal = Vec3f(f.world_vector(normal));
    sample.pdf_area = float(1.0 / areas_.total());
    return sample;
}

Bounds3f FrustumShape::bounds() const {
    Vec3d lower, upper;
    frustum_bounds(frustum_, lower, upper);
    Bounds3f b;
    b.extend(Vec3f(lower));
    b.extend(Vec3f(upper));
    return b;
}

void FrustumShape::bake(const Transform& to_world) {
    const double scale = to_world.similarity_scale();
    Frustum& f = frustum_;
    f.transform(to_world);
    f.height *= scale;
    f.base_radius *= scale;
    f.top_radius *= scale;
    build_area_distribution();
}

RTCGeometry FrustumShape::create_geometry(RTCDevice device) {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    return user_geometry::create<bounds_callback>(device, this, 1, intersect_callback, occluded_callback);
}

void FrustumShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const FrustumShape*>(args->geometryUserPtr);
    Vec3d lower, upper;
    frustum_bounds(self->frustum_, lower, upper);
    user_geometry::store_bounds(args->bounds_o, lower, upper);
}

void FrustumShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const FrustumShape*>(args->geometryUserPtr);
    std::optional<FrustumCrossing> found;
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) -> std::optional<double> {
            found = first_hit(self->frustum_, origin, direction, t_near, t_far);
            if (!found) return std::nullopt;
            return found->t;
        },
        [&](unsigned i, const Vec3d& origin, const Vec3d& direction, double t) {
            user_geometry::store_hit(args, i, float(t), frustum_normal(self->frustum_, found->part, origin + direction * t));
            RTCHitN_primID(RTCRayHitN_HitN(args->rayhit, args->N), args->N, i) = unsigned(found->part);  // see shading()
        });
}

void FrustumShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const FrustumShape*>(args->geometryUserPtr);
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    return first_hit(self->frustum_, origin, direction, t_near, t_far).has_value();
                                });
}

std::string FrustumShape::solid_problem() const {
    if (frustum_.caps) return {};
    return "an open " + type_ + " (\"caps\": false) encloses no volume; give it caps to use it as a solid";
}

void FrustumShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                std::vector<InsideSpan>& spans, QueryScratch&) const {
    if (!frustum_.caps) return;
    const FrustumCrossings crossings = frustum_crossings(frustum_, origin, direction);
    if (crossings.count < 2) return;
    const auto end = [&](const FrustumCrossing& c) {
        return BoundaryPoint{c.t, frustum_normal(frustum_, c.part, origin + direction * c.t), std::uint32_t(c.part), 0};
    };
    append_clipped_span({end(crossings.crossing[0]), end(crossings.crossing[1])}, t_min, t_max, spans);
}

LocalShading FrustumShape::shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const {
    const Frustum& f = frustum_;
    const auto part = FrustumPart(hit.primID);  // set by the intersect callback
    const Vec3d q = f.local_point(point);
    const double rho = std::hypot(q.x, q.y);
    const double cos_phi = rho > 0 ? q.x / rho : 1, sin_phi = rho > 0 ? q.y / rho : 0;
    double u = std::atan2(sin_phi, cos_phi) / kTwoPi;
    if (u < 0) u += 1;
    const Vec3d radial = f.world_vector({cos_phi, sin_phi, 0}), around = f.world_vector({-sin_phi, cos_phi, 0});
    LocalShading shading{.geometric_normal = geometric_normal, .normal = geometric_normal};
    if (part == FrustumPart::Side) {
        // p(u, v) = base + R(v)·(cos φ, sin φ) + v·h·axis, φ = 2πu, R(v) = r₀ + (r₁ − r₀)·v.
        const double v = std::clamp(q.z / f.height, 0.0, 1.0);
        shading.uv = {float(u), float(v)};
        shading.dpdu = Vec3f(around * (kTwoPi * f.radius_at(v * f.height)));
        shading.dpdv = Vec3f(radial * (f.top_radius - f.base_radius) + f.axis * f.height);
    } else {
        // p(u, v) = centre + v·r·(cos φ, sin φ).
        const double radius = part == FrustumPart::Top ? f.top_radius : f.base_radius;
        const double v = radius > 0 ? std::min(rho / radius, 1.0) : 0;  // a cone's apex, hit head on, is a "cap" of radius 0
        shading.uv = {float(u), float(v)};
        shading.dpdu = Vec3f(around * (kTwoPi * v * radius));
        shading.dpdv = Vec3f(radial * radius);
    }
    return shading;
}

Frustum frustum_from_end_points(const SceneNode& node, const std::string& top_key, const Vec3d& base, const Vec3d& top,
                                double base_radius, double top_radius, bool caps) {
    const double reach = std::max(base_radius, top_radius);
    if (max_component(max(abs(base), abs(top))) + reach > kWorldLimit)  // Embree silently drops bounds this large
        node.fail("the shape extends beyond 1e18 from the origin");
    const Vec3d axis = top - base;
    const double height = length(axis);
    // An axis shorter than rounding of the end points has no direction.
    if (!(height > 1e-12 * max_component(max(abs(base), abs(top)))))
        node.fail_at(top_key, "the axis has no length: it ends where it starts");
    Frustum f;
    static_cast<AxialFrame&>(f) = AxialFrame::around(base, axis / height);
    f.height = height;
    f.base_radius = base_radius;
    f.top_radius = top_radius;
    f.caps = caps;
    return f;
}

// The distance to the frustum's enclosing cylinder (a lower bound of the distance to the frustum): enough to clear
// the points CSG asks about, which are rarely near the side.
bool FrustumShape::certainly_outside(const Vec3d& point, double distance) const {
    if (!frustum_.caps) return false;
    const Vec3d q = frustum_.local_point(point);
    const double half = 0.5 * frustum_.height, widest = std::max(frustum_.base_radius, frustum_.top_radius);
    const double along = std::max(std::abs(q.z - half) - half, 0.0);
    const double radial = std::max(std::hypot(q.x, q.y) - widest, 0.0);
    constexpr double kRounding = 1e-12;  // of the frame and the distances, relative to the frustum's size
    return std::hypot(along, radial) > distance + kRounding * std::max(frustum_.height, widest);
}

}  // namespace isotrace
