#pragma once
// The point of a triangle mesh closest to a query point: an Embree point query over the mesh's BVH that shrinks
// its radius as it finds nearer triangles. For signed distances (mesh_distance_field.cpp) and for measuring how
// far a polygonised surface lies from the true one.
#include <embree3/rtcore.h>

#include <cstdint>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

struct ClosestTrianglePoint {
    double distance = 0;
    Vec3d point;
    std::uint32_t triangle = RTC_INVALID_GEOMETRY_ID;  // invalid when nothing lies within the search radius

    bool found() const { return triangle != RTC_INVALID_GEOMETRY_ID; }
};

class ClosestPointQuery {
public:
    // Keeps a reference to `mesh`, which must outlive the query object.
    explicit ClosestPointQuery(const TriangleMeshData& mesh);
    ~ClosestPointQuery();
    ClosestPointQuery(const ClosestPointQuery&) = delete;
    ClosestPointQuery& operator=(const ClosestPointQuery&) = delete;

    // The nearest point within `radius` of p (any radius, infinity included). Thread-safe.
    ClosestTrianglePoint nearest(const Vec3d& p, double radius) const;
    // The unit front normal of a triangle (counter-clockwise), or +z for a degenerate one.
    Vec3d triangle_normal(std::uint32_t triangle) const;

private:
    const TriangleMeshData& mesh_;
    RTCScene scene_ = nullptr;
};

}  // namespace isotrace
