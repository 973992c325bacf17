#include "geometry/mesh/mesh_crossing_scene.h"

namespace isotrace {
namespace {

// Embree hands the filter the context it was given: the crossings list travels behind it.
struct CollectingContext {
    RTCIntersectContext context;
    std::vector<MeshCrossing>* crossings;
};

void record_and_reject(const RTCFilterFunctionNArguments* args) {
    const auto* collecting = reinterpret_cast<const CollectingContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        collecting->crossings->push_back({RTCRayN_tfar(args->ray, args->N, i),
                                          {RTCHitN_Ng_x(args->hit, args->N, i), RTCHitN_Ng_y(args->hit, args->N, i),
                                           RTCHitN_Ng_z(args->hit, args->N, i)},
                                          RTCHitN_primID(args->hit, args->N, i)});
        args->valid[i] = 0;  // rejected: traversal goes on to the next crossing
    }
}

}  // namespace

MeshCrossingScene::MeshCrossingScene(RTCDevice device, RTCGeometry triangles) : scene_(rtcNewScene(device)) {
    rtcSetGeometryIntersectFilterFunction(triangles, record_and_reject);
    rtcCommitGeometry(triangles);
    rtcAttachGeometry(scene_, triangles);
    rtcReleaseGeometry(triangles);
    rtcCommitScene(scene_);
}

MeshCrossingScene::~MeshCrossingScene() { rtcReleaseScene(scene_); }

void MeshCrossingScene::crossings(const Vec3d& origin, const Vec3d& direction, double t_far,
                                  std::vector<MeshCrossing>& out) const {
    CollectingContext collecting{{}, &out};
    rtcInitIntersectContext(&collecting.context);
    RTCRayHit query{};
    query.ray.org_x = float(origin.x);
    query.ray.org_y = float(origin.y);
    query.ray.org_z = float(origin.z);
    query.ray.dir_x = float(direction.x);
    query.ray.dir_y = float(direction.y);
    query.ray.dir_z = float(direction.z);
    query.ray.tnear = 0;
    query.ray.tfar = float(t_far);
    query.ray.mask = 0xFFFFFFFFu;  // Debian's Embree is built with ray masks on
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &collecting.context, &query);
}

}  // namespace isotrace
