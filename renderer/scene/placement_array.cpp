#include "renderer/scene/placement_array.h"

#include <algorithm>
#include <limits>

#include "renderer/embree/user_geometry.h"
#include "renderer/math/box_corner.h"

namespace isotrace {
namespace {

// The ray of lane i carried into the placement's space: origin and direction by the record's matrix (in double,
// rounded once), its interval, mask and flags as they are (the map is affine, so t keeps its meaning).
RTCRay carried(const PlacementRecord& record, RTCRayN* rays, unsigned n, unsigned i) {
    const auto& m = record.from_world;
    const Vec3d o = user_geometry::ray_origin(rays, n, i), d = user_geometry::ray_direction(rays, n, i);
    const auto row = [&](int r, const Vec3d& v, double w) {
        return float(double(m[std::size_t(r * 4)]) * v.x + double(m[std::size_t(r * 4 + 1)]) * v.y +
                     double(m[std::size_t(r * 4 + 2)]) * v.z + double(m[std::size_t(r * 4 + 3)]) * w);
    };
    RTCRay local;
    local.org_x = row(0, o, 1);
    local.org_y = row(1, o, 1);
    local.org_z = row(2, o, 1);
    local.dir_x = row(0, d, 0);
    local.dir_y = row(1, d, 0);
    local.dir_z = row(2, d, 0);
    local.tnear = RTCRayN_tnear(rays, n, i);
    local.tfar = RTCRayN_tfar(rays, n, i);
    local.time = RTCRayN_time(rays, n, i);
    local.mask = RTCRayN_mask(rays, n, i);
    local.id = RTCRayN_id(rays, n, i);
    local.flags = RTCRayN_flags(rays, n, i);
    return local;
}

}  // namespace

std::string PlacementNames::default_name(std::uint32_t placement) const {
    return object + "[" + std::to_string(placement) + "]";
}

std::string PlacementNames::of(std::uint32_t placement) const {
    const auto found = std::lower_bound(own.begin(), own.end(), placement,
                                        [](const auto& entry, std::uint32_t index) { return entry.first < index; });
    return (found != own.end() && found->first == placement ? found->second : default_name(placement)) + part_suffix;
}

PlacementArray::PlacementArray(std::shared_ptr<Shape> shape, std::vector<const SceneObject*> variants,
                               std::vector<PlacementRecord> records, PlacementNames names)
    : shape_(std::move(shape)), variants_(std::move(variants)), records_(std::move(records)), names_(std::move(names)) {
    records_.shrink_to_fit();
}

RTCGeometry PlacementArray::create_geometry(RTCDevice device, RTCScene shape_scene) {
    shape_scene_ = shape_scene;
    // What the shape's scene can hit: Embree's bounds of it, which hold every primitive's box (the shape's own
    // bounds() may be tighter than the boxes its primitives report).
    RTCBounds b;
    rtcGetSceneBounds(shape_scene, &b);
    shape_scene_bounds_.lower = {b.lower_x, b.lower_y, b.lower_z};
    shape_scene_bounds_.upper = {b.upper_x, b.upper_y, b.upper_z};
    return user_geometry::create<bounds>(device, this, size(), intersect, occluded);
}

SceneObject PlacementArray::copy(std::uint32_t placement) const {
    SceneObject object = variant_of(placement);
    object.name = names_.of(placement);
    object.to_world = to_world(placement);
    return object;
}

std::size_t PlacementArray::memory_bytes() const {
    std::size_t bytes = sizeof(PlacementArray) + records_.capacity() * sizeof(PlacementRecord) +
                        variants_.capacity() * sizeof(const SceneObject*) + names_.object.capacity() +
                        names_.part_suffix.capacity() + names_.own.capacity() * sizeof(names_.own[0]);
    for (const auto& [index, name] : names_.own)
        bytes += name.capacity() > std::string().capacity() ? name.capacity() : 0;
    return bytes;
}

void PlacementArray::bounds(const RTCBoundsFunctionArguments* args) {
    const auto& array = *static_cast<const PlacementArray*>(args->geometryUserPtr);
    const Bounds3f& own = array.shape_scene_bounds_;
    if (own.empty()) {  // Embree leaves out a primitive whose box is not valid
        constexpr float kInfinity = std::numeric_limits<float>::infinity();
        *args->bounds_o = {kInfinity, kInfinity, kInfinity, 0, -kInfinity, -kInfinity, -kInfinity, 0};
        return;
    }
    const Transform to_world = array.to_world(args->primID);
    // Unbounded shapes reach the world's edge: their boxes are clipped to what Embree can hold.
    constexpr double kLargest = 1.844e18;
    Vec3d lower(kLargest, kLargest, kLargest), upper(-kLargest, -kLargest, -kLargest);
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p = to_world.point(box_corner(Vec3d(own.lower), Vec3d(own.upper), corner));
        for (int axis = 0; axis < 3; ++axis) {
            lower[axis] = std::clamp(std::min(lower[axis], p[axis]), -kLargest, kLargest);
            upper[axis] = std::clamp(std::max(upper[axis], p[axis]), -kLargest, kLargest);
        }
    }
    user_geometry::store_bounds(args->bounds_o, lower, upper);
}

// The hit keeps what shading needs: the shape's own primID, Ng (in the shape's space, as Embree's instances report
// it), u and v; geomID names this geometry and instID[0] the placement (there are no Embree instances to name).
void PlacementArray::intersect(const RTCIntersectFunctionNArguments* args) {
    const auto& array = *static_cast<const PlacementArray*>(args->geometryUserPtr);
    const PlacementRecord& record = array.records_[args->primID];
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        RTCRayHit local;
        local.ray = carried(record, rays, args->N, i);
        local.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        local.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        // Embree allows queries from a callback; the context carries the query's scratch on to the shape's callbacks.
        rtcIntersect1(array.shape_scene_, args->context, &local);
        if (local.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        RTCRayN_tfar(rays, args->N, i) = local.ray.tfar;
        RTCHitN_Ng_x(hits, args->N, i) = local.hit.Ng_x;
        RTCHitN_Ng_y(hits, args->N, i) = local.hit.Ng_y;
        RTCHitN_Ng_z(hits, args->N, i) = local.hit.Ng_z;
        RTCHitN_u(hits, args->N, i) = local.hit.u;
        RTCHitN_v(hits, args->N, i) = local.hit.v;
        RTCHitN_primID(hits, args->N, i) = local.hit.primID;
        RTCHitN_geomID(hits, args->N, i) = args->geomID;
        RTCHitN_instID(hits, args->N, i, 0) = args->primID;
    }
}

void PlacementArray::occluded(const RTCOccludedFunctionNArguments* args) {
    const auto& array = *static_cast<const PlacementArray*>(args->geometryUserPtr);
    const PlacementRecord& record = array.records_[args->primID];
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        RTCRay local = carried(record, args->ray, args->N, i);
        rtcOccluded1(array.shape_scene_, args->context, &local);
        if (local.tfar == -std::numeric_limits<float>::infinity())
            RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
    }
}

}  // namespace isotrace
