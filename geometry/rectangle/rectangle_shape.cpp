#include "geometry/rectangle/rectangle_shape.h"

#include <cmath>

#include "geometry/rectangle/spherical_rectangle.h"
#include "renderer/core/ray.h"
#include "renderer/params/world_limit.h"

namespace isotrace {
namespace {

// Edges this close to perpendicular (|cos| of their angle) count as a rectangle: the parametrisation's points are
// then off the true parallelogram by that fraction of an edge at most, and they are put back onto it (below).
constexpr double kPerpendicularCosine = 1e-6;

bool nearly_perpendicular(const Vec3d& a, const Vec3d& b) {
    return std::abs(dot(a, b)) <= kPerpendicularCosine * length(a) * length(b);
}

std::optional<SphericalRectangle> seen_from(const PlanarFrame& frame, const Vec3f& reference) {
    return SphericalRectangle::make(Vec3d(reference), frame.point(-0.5, -0.5), frame.axis_u(), frame.axis_v());
}

}  // namespace

RectangleShape::RectangleShape(const Vec3d& centre, const Vec3d& edge_u, const Vec3d& edge_v)
    : FlatShape(PlanarFrame(centre, edge_u, edge_v)) {
    frame_changed();
}

void RectangleShape::frame_changed() { perpendicular_ = nearly_perpendicular(frame().axis_u(), frame().axis_v()); }

Bounds3f RectangleShape::bounds() const {
    Bounds3f box;
    for (const double s : {-0.5, 0.5})
        for (const double t : {-0.5, 0.5}) box.extend(Vec3f(frame().point(s, t)));
    return box;
}

bool RectangleShape::covers(const std::array<double, 2>& st) const {
    return std::abs(st[0]) <= 0.5 && std::abs(st[1]) <= 0.5;
}

LocalShading RectangleShape::shading(const RTCHit&, const Vec3f& geometric_normal, const Vec3d& point) const {
    const auto [s, t] = frame().coordinates(point);
    return {.geometric_normal = geometric_normal,
            .normal = geometric_normal,
            .uv = {float(s + 0.5), float(t + 0.5)},
            .dpdu = Vec3f(frame().axis_u()),
            .dpdv = Vec3f(frame().axis_v())};
}

SurfaceSample RectangleShape::sample_surface(std::array<float, 2> u) const {
    SurfaceSample sample;
    sample.position = Vec3f(frame().point(double(u[0]) - 0.5, double(u[1]) - 0.5));
    sample.normal = Vec3f(frame().normal());
    sample.pdf_area = float(1 / frame().cell_area());
    return sample;
}

SolidAngleSample RectangleShape::sample_solid_angle(const Vec3f& reference, std::array<float, 2> u) const {
    if (!perpendicular_) return {};
    const std::optional<SphericalRectangle> seen = seen_from(frame(), reference);
    if (!seen) return {};
    const auto [x, y] = seen->sample({double(u[0]), double(u[1])});
    SolidAngleSample sample;
    sample.position = Vec3f(frame().point(x - 0.5, y - 0.5));
    sample.normal = Vec3f(frame().normal());
    sample.pdf_solid_angle = float(1 / seen->solid_angle());
    return sample;
}

float RectangleShape::solid_angle_pdf(const Vec3f& reference) const {
    if (!perpendicular_) return 0;
    const std::optional<SphericalRectangle> seen = seen_from(frame(), reference);
    return seen ? float(1 / seen->solid_angle()) : 0.0f;
}

namespace {

Vec3d edge(const SceneNode& node, const std::string& key, const Vec3d& fallback) {
    if (!node.has(key)) return fallback;
    const Vec3d e = node.vec3(key);
    if (!(length(e) > 0) || !within_world(e)) node.fail_at(key, "an edge must be a non-zero vector within 1e18");
    return e;
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    const Vec3d centre = node.has("center") ? world_point(node, "center") : Vec3d{0, 0, 0};
    Vec3d edge_u{1, 0, 0}, edge_v{0, 0, -1};  // facing +y
    if (node.has("size")) {
        if (node.has("edge_u") || node.has("edge_v")) node.fail("give either \"size\" or \"edge_u\"/\"edge_v\", not both");
        const std::vector<double> size = node.numbers("size", 2, world_length());
        edge_u = {size[0], 0, 0};
        edge_v = {0, 0, -size[1]};
    } else {
        edge_u = edge(node, "edge_u", edge_u);
        edge_v = edge(node, "edge_v", edge_v);
        if (!nearly_perpendicular(edge_u, edge_v))
            node.fail_at("edge_v", "the edges must be perpendicular (shear a rectangle with the object's transform)");
    }
    if (max_component(abs(centre) + (abs(edge_u) + abs(edge_v)) * 0.5) > kWorldLimit)
        node.fail(beyond_world_problem("the rectangle"));
    return std::make_unique<RectangleShape>(centre, edge_u, edge_v);
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "rectangle",
                         "rectangle (an area light sampled by solid angle); center, size [w, h] or edge_u, edge_v",
                         create)

}  // namespace isotrace
