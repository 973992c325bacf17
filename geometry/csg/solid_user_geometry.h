#pragma once
// An Embree user geometry of one primitive whose surface is the boundary of a Solid: a ray's hit is the solid's
// first surface point in (t_near, t_far). Rays that start inside hit the exit. The box and
// the CSG shape are traced this way; the hit's primID carries the part (leaf surface) the point lies on. The spans
// are asked with the query's scratch (QueryContext, renderer/embree/query_context.h).
#include <embree3/rtcore.h>

#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

class SolidUserGeometry {
public:
    // `solid` must outlive the geometry; `counter_slot` is the geometry type's slot in render_counters. An empty
    // `bounds` (nothing can be inside) gives a geometry without primitives.
    RTCGeometry create(RTCDevice device, const Solid& solid, int counter_slot, const Bounds3f& bounds);

private:
    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    const Solid* solid_ = nullptr;
    int counter_slot_ = 0;
    Bounds3f bounds_;
};

}  // namespace isotrace
