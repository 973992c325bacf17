#pragma once
// A box: the axis-aligned box centre ± half_size in its own frame, placed by an affine transform that is always
// baked (an affine image of a box is a parallelepiped, traced exactly by the slab method in the box frame).
// It is a closed solid, so CSG can combine it.
#include <optional>

#include "geometry/csg/solid_user_geometry.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

class BoxShape final : public Shape, public Solid {
public:
    BoxShape(const Vec3d& centre, const Vec3d& half_size);

    std::string type_name() const override { return "box"; }
    std::unique_ptr<ImplicitField> implicit_field() const override;
    std::size_t primitive_count() const override { return 1; }
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    bool can_bake(const Transform&) const override { return true; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;

    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;
    bool certainly_outside(const Vec3d& point, double distance) const override;

    // The box is half_size() around the origin of its frame, which to_object() places.
    const Vec3d& half_size() const { return half_size_; }
    const Transform& to_object() const { return to_object_; }

private:
    // The one span of the line inside the box (unclipped), if the line passes through its interior. A line in a
    // face plane, or touching only an edge or corner, misses.
    std::optional<InsideSpan> crossing(const Vec3d& origin, const Vec3d& direction) const;

    Vec3d half_size_;
    Transform to_object_;    // box frame (centred at the origin) -> object/world space
    Transform from_object_;  // its inverse
    SolidUserGeometry geometry_;
};

}  // namespace isotrace
