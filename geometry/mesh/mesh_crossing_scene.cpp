#include "geometry/mesh/mesh_crossing_scene.h"

#include <algorithm>

#include "renderer/embree/triangle_hit.h"

namespace isotrace {
namespace {

// Embree hands the filter the context it was given: what the traversal collects travels behind it.
struct CollectingContext {
    RTCIntersectContext context;
    std::vector<MeshCrossing>* crossings;  // null when only their number is asked for
    std::size_t count = 0;
};

void record_and_reject(const RTCFilterFunctionNArguments* args) {
    auto* collecting = reinterpret_cast<CollectingContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        ++collecting->count;
        if (collecting->crossings)
            collecting->crossings->push_back(
                {RTCRayN_tfar(args->ray, args->N, i),
                 {RTCHitN_Ng_x(args->hit, args->N, i), RTCHitN_Ng_y(args->hit, args->N, i),
                  RTCHitN_Ng_z(args->hit, args->N, i)},
                 RTCHitN_primID(args->hit, args->N, i)});
        args->valid[i] = 0;  // rejected: traversal goes on to the next crossing
    }
}

}  // namespace

MeshCrossingScene::MeshCrossingScene(RTCDevice device, RTCGeometry triangles)
    : scene_(rtcNewScene(device)),
      positions_(static_cast<const Vec3f*>(rtcGetGeometryBufferData(triangles, RTC_BUFFER_TYPE_VERTEX, 0))),
      corners_(static_cast<const std::array<std::uint32_t, 3>*>(
          rtcGetGeometryBufferData(triangles, RTC_BUFFER_TYPE_INDEX, 0))) {
    static_assert(sizeof(Vec3f) == 3 * sizeof(float) && sizeof(corners_[0]) == 3 * sizeof(std::uint32_t));
    rtcSetGeometryIntersectFilterFunction(triangles, record_and_reject);
    rtcCommitGeometry(triangles);
    rtcAttachGeometry(scene_, triangles);
    // Which triangles a ray crosses decides inside from outside: robust traversal keeps a ray through an edge from
    // being culled by the rounding of its box tests, which differs between Embree's kernels and CPU makers.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcReleaseGeometry(triangles);
    rtcCommitScene(scene_);
}

MeshCrossingScene::~MeshCrossingScene() { rtcReleaseScene(scene_); }

void MeshCrossingScene::crossings(const Vec3d& origin, const Vec3d& direction, double t_far,
                                  std::vector<MeshCrossing>& out) const {
    const std::size_t first = out.size();
    traverse(origin, direction, t_far, &out);
    // Embree's distances come from an approximate reciprocal whose last bits vary between CPU makers; which
    // triangles are crossed does not (triangle_hit.h). So each distance is solved again, for the ray as given.
    for (std::size_t i = first; i < out.size(); ++i) {
        const std::array<std::uint32_t, 3>& corners = corners_[out[i].triangle];
        TriangleSolution<double> solved;
        if (!solve_triangle_hit(origin, direction, Vec3d(positions_[corners[0]]), Vec3d(positions_[corners[1]]),
                                Vec3d(positions_[corners[2]]), solved))
            continue;
        out[i].t = solved.t;
        out[i].normal = solved.normal;
        out[i].on_edge = std::min({solved.u, solved.v, 1 - solved.u - solved.v}) < kEdgeBand;
    }
}

std::size_t MeshCrossingScene::crossing_count(const Vec3d& origin, const Vec3d& direction, double t_far) const {
    return traverse(origin, direction, t_far, nullptr);
}

std::size_t MeshCrossingScene::traverse(const Vec3d& origin, const Vec3d& direction, double t_far,
                                        std::vector<MeshCrossing>* out) const {
    CollectingContext collecting{{}, out};
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
    return collecting.count;
}

}  // namespace isotrace
