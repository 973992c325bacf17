#pragma once
// FlatShape: what the plane, the disk and the rectangle share. Each is the part of a PlanarFrame's plane that its
// outline covers (covers(s, t)), one Embree user-geometry primitive intersected in double: a ray hits where it
// crosses the plane strictly inside (t_near, t_far) at a covered point; a ray parallel to the plane (also one lying
// in it) misses. Every affine placement is baked (the frame maps exactly), so these shapes are never instanced.
#include <array>
#include <optional>

#include "geometry/plane/planar_frame.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

class FlatShape : public Shape {
public:
    explicit FlatShape(const PlanarFrame& frame) : frame_(frame) {}

    std::size_t primitive_count() const override { return 1; }
    bool counts_intersection_tests() const override { return true; }
    bool can_bake(const Transform&) const override { return true; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;
    bool has_uv() const override { return true; }

    // The hit parameter of origin + t·direction, if it crosses a covered point in (t_near, t_far).
    std::optional<double> first_hit(const Vec3d& origin, const Vec3d& direction, double t_near, double t_far) const;
    const PlanarFrame& frame() const { return frame_; }
    // Whether the point (s, t) of the frame belongs to the surface (points on the outline do).
    virtual bool covers(const std::array<double, 2>& st) const = 0;

protected:
    // Called after bake() has mapped the frame, for shapes that derive data from it.
    virtual void frame_changed() {}

private:
    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    PlanarFrame frame_;
    Bounds3f embree_bounds_;  // bounds(), taken when the geometry is created
    int counter_slot_ = 0;
};

}  // namespace isotrace
