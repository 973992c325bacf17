#include "geometry/mesh/closest_triangle_point.h"

#include <cmath>
#include <cstring>

#include "renderer/embree/embree_device.h"

namespace isotrace {
namespace {

// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, §5.1.5: by Voronoi region).
Vec3d closest_on_triangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const Vec3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3d bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const Vec3d cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denominator = va + vb + vc;
    if (!(denominator > 0)) return a;  // a degenerate triangle: any of its points will do
    return a + ab * (vb / denominator) + ac * (vc / denominator);
}

struct Search {
    const TriangleMeshData* mesh;
    Vec3d point;
    ClosestTrianglePoint best;
};

// Float rounding of the query point, as a margin that keeps Embree's culling conservative.
float widened(const Vec3d& p, double radius) {
    return std::isfinite(radius) ? float(radius + 1e-6 * (length(p) + radius)) : INFINITY;
}

bool visit_triangle(RTCPointQueryFunctionArguments* args) {
    auto& search = *static_cast<Search*>(args->userPtr);
    const auto& t = search.mesh->triangles[args->primID];
    const Vec3d c = closest_on_triangle(search.point, Vec3d(search.mesh->positions[t[0]]),
                                        Vec3d(search.mesh->positions[t[1]]), Vec3d(search.mesh->positions[t[2]]));
    const double d = length(search.point - c);
    if (!(d <= search.best.distance)) return false;
    search.best = {d, c, args->primID};
    args->query->radius = widened(search.point, d);
    return true;
}

}  // namespace

ClosestPointQuery::ClosestPointQuery(const TriangleMeshData& mesh) : mesh_(mesh), scene_(rtcNewScene(embree_device())) {
    RTCGeometry geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree-owned copies: they come padded for its 16-byte vector loads.
    auto* vertices = static_cast<Vec3f*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 sizeof(Vec3f), mesh.positions.size()));
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), mesh.triangles.size()));
    if (vertices && indices) {
        std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(Vec3f));
        std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
    check_embree("closest-point query");
}

ClosestPointQuery::~ClosestPointQuery() { rtcReleaseScene(scene_); }

ClosestTrianglePoint ClosestPointQuery::nearest(const Vec3d& p, double radius) const {
    Search search{&mesh_, p, {radius, {}, RTC_INVALID_GEOMETRY_ID}};
    RTCPointQuery query;
    query.x = float(p.x);
    query.y = float(p.y);
    query.z = float(p.z);
    query.time = 0;
    query.radius = widened(p, radius);
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(scene_, &query, &context, visit_triangle, &search);
    return search.best;
}

Vec3d ClosestPointQuery::triangle_normal(std::uint32_t triangle) const {
    const auto& t = mesh_.triangles[triangle];
    const Vec3d a(mesh_.positions[t[0]]), b(mesh_.positions[t[1]]), c(mesh_.positions[t[2]]);
    const Vec3d n = cross(b - a, c - a);
    const double l = length(n);
    return l > 0 ? n / l : Vec3d{0, 0, 1};
}

}  // namespace isotrace
