#include "geometry/torus/torus_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/csg/inside_span_list.h"
#include "renderer/core/ray.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {
namespace {

constexpr double kPi = std::numbers::pi, kTwoPi = 2 * std::numbers::pi;

std::optional<double> first_hit(const Torus& torus, const Vec3d& origin, const Vec3d& direction, double t_near,
                                double t_far) {
    const TorusCrossings crossings = torus_crossings(torus, origin, direction, t_near, t_far, true);
    if (crossings.count == 0) return std::nullopt;
    return crossings.t[0];
}

// The angle θ ∈ [−π, π) around the tube at which the fraction w of the area lies below: F(θ) = w with
// F(θ) = (R·(θ + π) + r·sin θ) / (2πR), increasing (R > r). Newton steps kept inside a shrinking bracket, bisection
// where they leave it; 64 halvings exhaust a double, so the loop is bounded.
double tube_angle(double w, double R, double r) {
    double lo = -kPi, hi = kPi, theta = kTwoPi * w - kPi;
    for (int i = 0; i < 64 && hi - lo > 1e-15; ++i) {
        const double excess = (R * (theta + kPi) + r * std::sin(theta)) / (kTwoPi * R) - w;
        if (excess == 0) break;
        (excess > 0 ? hi : lo) = theta;
        const double next = theta - excess * kTwoPi * R / (R + r * std::cos(theta));
        theta = next > lo && next < hi ? next : 0.5 * (lo + hi);
    }
    return theta;
}

}  // namespace

Bounds3f TorusShape::bounds() const {
    Vec3d lower, upper;
    torus_bounds(torus_, lower, upper);
    Bounds3f b;
    b.extend(Vec3f(lower));
    b.extend(Vec3f(upper));
    return b;
}

void TorusShape::bake(const Transform& to_world) {
    const double scale = to_world.similarity_scale();
    torus_.transform(to_world);
    torus_.major_radius *= scale;
    torus_.minor_radius *= scale;
}

RTCGeometry TorusShape::create_geometry(RTCDevice device) {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    return user_geometry::create<bounds_callback>(device, this, 1, intersect_callback, occluded_callback);
}

void TorusShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const TorusShape*>(args->geometryUserPtr);
    Vec3d lower, upper;
    torus_bounds(self->torus_, lower, upper);
    user_geometry::store_bounds(args->bounds_o, lower, upper);
}

void TorusShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const TorusShape*>(args->geometryUserPtr);
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
            return first_hit(self->torus_, origin, direction, t_near, t_far);
        },
        [&](unsigned i, const Vec3d& origin, const Vec3d& direction, double t) {
            user_geometry::store_hit(args, i, float(t), torus_gradient(self->torus_, origin + direction * t));
        });
}

void TorusShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const TorusShape*>(args->geometryUserPtr);
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    return first_hit(self->torus_, origin, direction, t_near, t_far).has_value();
                                });
}

void TorusShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                              std::vector<InsideSpan>& spans, QueryScratch&) const {
    // The whole line's crossings: it starts outside (beyond the bounding sphere), so they alternate enter, exit. An
    // odd count (a crossing lost to rounding at a grazing contact) leaves the last one unpaired; it is dropped.
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const TorusCrossings crossings = torus_crossings(torus_, origin, direction, -kInfinity, kInfinity, false);
    const auto end = [&](double t) {
        return BoundaryPoint{t, torus_gradient(torus_, origin + direction * t), 0, 0};
    };
    for (int i = 0; i + 1 < crossings.count; i += 2)
        append_clipped_span({end(crossings.t[std::size_t(i)]), end(crossings.t[std::size_t(i + 1)])}, t_min, t_max,
                            spans);
}

LocalShading TorusShape::shading(const RTCHit&, const Vec3f& geometric_normal, const Vec3d& point) const {
    const Torus& torus = torus_;
    const Vec3d q = torus.local_point(point);
    const double rho = std::hypot(q.x, q.y);
    const double cos_phi = rho > 0 ? q.x / rho : 1, sin_phi = rho > 0 ? q.y / rho : 0;
    const double theta = std::atan2(q.z, rho - torus.major_radius);
    double u = std::atan2(sin_phi, cos_phi) / kTwoPi, v = theta / kTwoPi;
    if (u < 0) u += 1;
    if (v < 0) v += 1;
    // p(u, v) = c + (R + r cos θ)·(cos φ, sin φ) + r sin θ·axis, φ = 2πu, θ = 2πv.
    const Vec3d radial = torus.world_vector({cos_phi, sin_phi, 0}), around = torus.world_vector({-sin_phi, cos_phi, 0});
    const double R = torus.major_radius, r = torus.minor_radius;
    return {.geometric_normal = geometric_normal,
            .normal = geometric_normal,
            .uv = {float(u), float(v)},
            .dpdu = Vec3f(around * (kTwoPi * (R + r * std::cos(theta)))),
            .dpdv = Vec3f((radial * -std::sin(theta) + torus.axis * std::cos(theta)) * (kTwoPi * r))};
}

float TorusShape::surface_area() const {
    return float(4 * kPi * kPi * torus_.major_radius * torus_.minor_radius);
}

SurfaceSample TorusShape::sample_surface(std::array<float, 2> u) const {
    const double R = torus_.major_radius, r = torus_.minor_radius;
    const double theta = tube_angle(u[0], R, r), phi = kTwoPi * u[1];
    const Vec3d radial(std::cos(phi), std::sin(phi), 0);
    const Vec3d normal = radial * std::cos(theta) + Vec3d(0, 0, std::sin(theta));
    SurfaceSample sample;
    sample.position = Vec3f(torus_.origin + torus_.world_vector(radial * R + normal * r));
    sample.normal = Vec3f(torus_.world_vector(normal));
    sample.pdf_area = float(1 / (4 * kPi * kPi * R * r));
    return sample;
}

namespace {

std::unique_ptr<Shape> create(const SceneNode& node) {
    const Vec3d centre = node.vec3_or("center", {0, 0, 0});
    const Vec3d axis = node.vec3_or("axis", {0, 1, 0});
    const double major = node.number_or("major_radius", 1.0, NumberRange::positive());
    const double minor = node.number_or("minor_radius", 0.25, NumberRange::positive());
    if (!(minor < major))
        node.fail_at("minor_radius", "the minor radius must be less than the major radius (a ring torus)");
    if (!(length(axis) > 0) || !std::isfinite(length(axis))) node.fail_at("axis", "the axis must be a non-zero vector");
    if (max_component(abs(centre)) + major + minor > kWorldLimit)  // Embree silently drops bounds this large
        node.fail("the torus extends beyond 1e18 from the origin");
    Torus torus;
    static_cast<AxialFrame&>(torus) = AxialFrame::around(centre, normalize(axis));
    torus.major_radius = major;
    torus.minor_radius = minor;
    return std::make_unique<TorusShape>(torus);
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "torus", "ring torus; center, axis, major_radius, minor_radius", create)

bool TorusShape::certainly_outside(const Vec3d& point, double distance) const {
    constexpr double kRounding = 1e-12;  // of the distance, relative to the torus's size
    return torus_distance(torus_, point) > distance + kRounding * torus_.major_radius;
}

}  // namespace isotrace
