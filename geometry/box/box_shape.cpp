#include "geometry/box/box_shape.h"

#include <algorithm>
#include <cmath>

#include "geometry/csg/inside_span_list.h"
#include "geometry/csg/transformed_bounds.h"
#include "renderer/core/ray.h"
#include "renderer/core/render_counters.h"
#include "renderer/math/line_box_clip.h"

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
    // A line parallel to a slab must lie strictly inside it: one in the plane of a face only grazes the box, and
    // grazing contacts are misses (docs/decisions.md), although the closed clip keeps them; so is a line that
    // meets the box in one point (the strict test below).
    for (int axis = 0; axis < 3; ++axis)
        if (d[axis] == 0 && !(std::abs(o[axis]) < half_size_[axis])) return std::nullopt;
    const std::optional<LineBoxClip> clip = clip_line_to_box(-half_size_, half_size_, o, d, -INFINITY, INFINITY);
    if (!clip || !(clip->t_enter < clip->t_exit)) return std::nullopt;
    // The outward normal of the face an end lies on, in the box frame ((0, 0, 1) for an end at infinity, where
    // it is never used); normals map by the inverse transpose (they are gradients of the box's inside function).
    const auto face_normal = [&](int axis, double outward) {
        if (axis < 0) return normalize(to_object_.normal(Vec3d{0, 0, 1}));
        Vec3d n{};
        n[axis] = d[axis] > 0 ? outward : -outward;
        return normalize(to_object_.normal(n));
    };
    return InsideSpan{{clip->t_enter, face_normal(clip->enter_axis, -1), 0, 0},
                      {clip->t_exit, face_normal(clip->exit_axis, 1), 0, 0}};
}

void BoxShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                            std::vector<InsideSpan>& spans, QueryScratch&) const {
    if (const auto span = crossing(origin, direction)) append_clipped_span(*span, t_min, t_max, spans);
}

namespace {

std::unique_ptr<Shape> create(const SceneNode& node) {
    const Vec3d centre = node.vec3_or("center", {0, 0, 0});
    const Vec3d half_size = node.vec3_or("half_size", {1, 1, 1});
    if (!(std::min({half_size.x, half_size.y, half_size.z}) > 0)) node.fail_at("half_size", "every half size must be positive");
    if (max_component(abs(centre) + half_size) > kWorldLimit)  // Embree silently drops bounds this large
        node.fail("box extends beyond 1e18 from the origin");
    return std::make_unique<BoxShape>(centre, half_size);
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "box", "box (a closed solid); center, half_size [hx, hy, hz]", create)

// The point's distance to the box, in the box frame, scaled back to the object's (a box placed by a map that is not
// a similarity is left undecided).
bool BoxShape::certainly_outside(const Vec3d& point, double distance) const {
    const double scale = to_object_.similarity_scale();
    if (!(scale > 0)) return false;
    const Vec3d local = from_object_.point(point);
    const Vec3d gap(std::max(std::abs(local.x) - half_size_.x, 0.0), std::max(std::abs(local.y) - half_size_.y, 0.0),
                    std::max(std::abs(local.z) - half_size_.z, 0.0));
    constexpr double kRounding = 1e-12;  // of the map and the gap, relative to the box's size
    return length(gap) * scale > distance + kRounding * scale * max_component(half_size_);
}

}  // namespace isotrace
