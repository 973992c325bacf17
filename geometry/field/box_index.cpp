#include "geometry/field/box_index.h"

#include <cmath>
#include <stdexcept>

#include "renderer/embree/embree_device.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {
namespace {

struct QueryState {
    const std::vector<FieldBox>* boxes;
    Vec3d centre;
    double radius;
    bool (*callback)(void*, std::uint32_t);
    void* user;
    bool stopped = false;
};

void box_bounds(const RTCBoundsFunctionArguments* args) {
    const auto& boxes = *static_cast<const std::vector<FieldBox>*>(args->geometryUserPtr);
    const FieldBox& box = boxes[args->primID];
    user_geometry::store_bounds(args->bounds_o, box.lower, box.upper);
}

bool visit_box(RTCPointQueryFunctionArguments* args) {
    auto& state = *static_cast<QueryState*>(args->userPtr);
    if (state.stopped) return false;
    if ((*state.boxes)[args->primID].distance(state.centre) <= state.radius &&
        !state.callback(state.user, args->primID))
        state.stopped = true;
    return false;  // the query radius stays as it is
}

}  // namespace

BoxIndex::BoxIndex(std::vector<FieldBox> boxes) : boxes_(std::move(boxes)), scene_(rtcNewScene(embree_device())) {
    RTCGeometry geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(boxes_.size()));
    thread_sanitizer::publish(&boxes_);
    rtcSetGeometryUserData(geometry, &boxes_);
    rtcSetGeometryBoundsFunction(geometry, user_geometry::announced_bounds<box_bounds>, nullptr);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
    check_embree("box index");
}

BoxIndex::~BoxIndex() { rtcReleaseScene(scene_); }

void BoxIndex::query(const Vec3d& centre, double radius, Callback callback, void* user) const {
    QueryState state{&boxes_, centre, radius, callback, user};
    RTCPointQuery point;
    point.x = float(centre.x);
    point.y = float(centre.y);
    point.z = float(centre.z);
    point.time = 0;
    // Widened by the centre's rounding to float, so that Embree's culling stays conservative.
    point.radius = float(radius + 1e-6 * (length(centre) + radius));
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(scene_, &point, &context, visit_box, &state);
}

}  // namespace isotrace
