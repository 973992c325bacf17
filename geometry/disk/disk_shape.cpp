#include "geometry/disk/disk_shape.h"

#include <cmath>
#include <numbers>

#include "renderer/core/ray.h"
#include "renderer/params/world_limit.h"

namespace isotrace {

DiskShape::DiskShape(const Vec3d& centre, const Vec3d& normal, double radius, double inner_ratio)
    : FlatShape(frame_facing(centre, normal, radius)), inner_ratio_(inner_ratio) {}

Bounds3f DiskShape::bounds() const {
    // The ellipse c + cos φ·a + sin φ·b reaches sqrt(a_k² + b_k²) from the centre along axis k.
    const Vec3d& a = frame().axis_u();
    const Vec3d& b = frame().axis_v();
    const Vec3d reach(std::hypot(a.x, b.x), std::hypot(a.y, b.y), std::hypot(a.z, b.z));
    Bounds3f box;
    box.extend(Vec3f(frame().origin() - reach));
    box.extend(Vec3f(frame().origin() + reach));
    return box;
}

bool DiskShape::covers(const std::array<double, 2>& st) const {
    const double rho_squared = st[0] * st[0] + st[1] * st[1];
    return rho_squared <= 1 && rho_squared >= inner_ratio_ * inner_ratio_;
}

LocalShading DiskShape::shading(const RTCHit&, const Vec3f& geometric_normal, const Vec3d& point) const {
    const auto [s, t] = frame().coordinates(point);
    const double rho = std::hypot(s, t);
    const double phi = std::atan2(t, s);
    const double u = phi < 0 ? phi / (2 * std::numbers::pi) + 1 : phi / (2 * std::numbers::pi);
    // p = c + ρ(cos φ·a + sin φ·b), φ = 2πu, ρ = v.
    const Vec3d radial = frame().axis_u() * std::cos(phi) + frame().axis_v() * std::sin(phi);
    const Vec3d around = (frame().axis_v() * std::cos(phi) - frame().axis_u() * std::sin(phi)) * (2 * std::numbers::pi * rho);
    return {.geometric_normal = geometric_normal,
            .normal = geometric_normal,
            .uv = {float(u), float(rho)},
            .dpdu = Vec3f(around),
            .dpdv = Vec3f(radial)};
}

SurfaceSample DiskShape::sample_surface(std::array<float, 2> u) const {
    const double inner_squared = inner_ratio_ * inner_ratio_;
    const double rho = std::sqrt(inner_squared + double(u[0]) * (1 - inner_squared));
    const double phi = 2 * std::numbers::pi * double(u[1]);
    SurfaceSample sample;
    sample.position = Vec3f(frame().point(rho * std::cos(phi), rho * std::sin(phi)));
    sample.normal = Vec3f(frame().normal());
    sample.pdf_area = 1 / surface_area();
    return sample;
}

float DiskShape::surface_area() const {
    return float(std::numbers::pi * (1 - inner_ratio_ * inner_ratio_) * frame().cell_area());
}

namespace {

std::unique_ptr<Shape> create(const SceneNode& node) {
    const Vec3d centre = node.has("center") ? world_point(node, "center") : Vec3d{0, 0, 0};
    const Vec3d normal = node.has("normal") ? unit_direction(node, "normal") : Vec3d{0, 1, 0};
    const double radius = node.number_or("radius", 1.0, world_length());
    const double inner = node.number_or("inner_radius", 0.0, {0, radius, false, true});
    if (max_component(abs(centre)) + radius > kWorldLimit) node.fail(beyond_world_problem("the disk"));
    return std::make_unique<DiskShape>(centre, normal, radius, inner / radius);
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "disk", "disk or annulus; center, normal, radius, inner_radius", create)

}  // namespace isotrace
