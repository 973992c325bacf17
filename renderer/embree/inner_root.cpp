#include "renderer/embree/inner_root.h"

#include "renderer/embree/user_geometry.h"

namespace isotrace {
namespace {

void no_hit(const RTCIntersectFunctionNArguments*) {}
void no_occlusion(const RTCOccludedFunctionNArguments*) {}

}  // namespace

void InnerRootSentinel::bounds(const RTCBoundsFunctionArguments* args) {
    const Vec3d point(static_cast<const InnerRootSentinel*>(args->geometryUserPtr)->point_);
    user_geometry::store_bounds(args->bounds_o, point, point);
}

void InnerRootSentinel::add_to(RTCDevice device, RTCScene scene, const Vec3f& point) {
    point_ = point;
    RTCGeometry geometry = user_geometry::create<bounds>(device, this, 1, no_hit, no_occlusion);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
}

}  // namespace isotrace
