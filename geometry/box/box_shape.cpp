#include "geometry/box/box_shape.h"

#include <algorithm>
#include <cmath>

#include "geometry/csg/inside_span_list.h"
#include "geometry/csg/transformed_bounds.h"
#include "renderer/core/render_counters.h"

namespace isotrace {

BoxShape::BoxShape(const Vec3d& centre, const Vec3d& half_size)
    : half_size_(half_size), to_object_(Transform::translate(centre)), from_object_(to_object_.inverse()) {}

Bounds3f BoxShape::bounds() const { return transformed_bounds(-half_size_, half_size_, to_object_); }

void BoxShape::bake(const Transform& to_world) {
    to_object_ = to_world * to_object_;
    from_object_ = to_object_.inverse();
}

RTCGeometry BoxShape::create_geometry(RTCDevice device) {
    return geometry_.create(device, *this, counters::geometry_type_slot(type_name(), true), bounds());
}

std::optional<InsideSpan> BoxShape::crossing(const Vec3d& origin, const Vec3d& direction) const {
    const Vec3d o = from_object_.point(origin), d = from_object_.vector(direction);
    double t_enter = -INFINITY, t_exit = INFINITY;
    Vec3d enter_normal{0, 0, 1}, exit_normal{0, 0, 1};  // in the box frame (only meaningful when t is finite)
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0) {
            if (!(std::abs(o[axis]) < half_size_[axis])) return std::nullopt;  // parallel to the slab, not inside it
            continue;
        }
        const double side = d[axis] > 0 ? 1.0 : -1.0;  // the slab face the ray leaves through
        const double t_near = (-side * half_size_[axis] - o[axis]) / d[axis];
        const double t_far = (side * half_size_[axis] - o[axis]) / d[axis];
        if (t_near > t_enter) {
            t_enter = t_near;
            enter_normal = {};
            enter_normal[axis] = -side;
        }
        if (t_far < t_exit) {
            t_exit = t_far;
            exit_normal = {};
            exit_normal[axis] = side;
        }
    }
    if (!(t_enter < t_exit)) return std::nullopt;
    // Outward normals map by the inverse transpose (they are gradients of the box's inside function).
    return InsideSpan{{t_enter, normalize(to_object_.normal(enter_normal)), 0, 0},
                      {t_exit, normalize(to_object_.normal(exit_normal)), 0, 0}};
}

void BoxShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                            std::vector<InsideSpan>& spans) const {
    if (const auto span = crossing(origin, direction)) append_clipped_span(*span, t_min, t_max, spans);
}

namespace {

std::unique_ptr<Shape> create(const SceneNode& node) {
    const Vec3d centre = node.vec3_or("center", {0, 0, 0});
    const Vec3d half_size = node.vec3_or("half_size", {1, 1, 1});
    if (!(std::min({half_size.x, half_size.y, half_size.z}) > 0)) node.fail_at("half_size", "every half size must be positive");
    if (max_component(abs(centre) + half_size) > 1e18)  // Embree silently drops bounds this large
        node.fail("box extends beyond 1e18 from the origin");
    return std::make_unique<BoxShape>(centre, half_size);
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "box", "box (a closed solid); center, half_size [hx, hy, hz]", create)

}  // namespace isotrace
