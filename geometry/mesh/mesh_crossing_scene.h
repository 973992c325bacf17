#pragma once
// A private Embree scene holding a mesh's triangles whose filter rejects every hit after recording it, so one
// traversal lists every crossing of a ray with the surface (for the mesh's inside spans).
#include <embree3/rtcore.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/math/vec3.h"

namespace isotrace {

struct MeshCrossing {
    double t = 0;
    Vec3d normal;  // the triangle's front normal (counter-clockwise), not normalised
    std::uint32_t triangle = 0;
    // Within kEdgeBand of an edge of its triangle, in barycentric terms: where Embree's float test decides by its
    // rounding whether the ray crosses this triangle, its neighbour, both or neither.
    bool on_edge = false;
};

inline constexpr double kEdgeBand = 1e-6;

class MeshCrossingScene {
public:
    // Takes over `triangles`, a committed triangle geometry.
    MeshCrossingScene(RTCDevice device, RTCGeometry triangles);
    ~MeshCrossingScene();
    MeshCrossingScene(const MeshCrossingScene&) = delete;
    MeshCrossingScene& operator=(const MeshCrossingScene&) = delete;

    // Appends every crossing of origin + t·direction with t in [0, t_far], in no particular order. Thread-safe.
    void crossings(const Vec3d& origin, const Vec3d& direction, double t_far, std::vector<MeshCrossing>& out) const;
    // How many crossings crossings() would append (a parity test needs no list). Thread-safe.
    std::size_t crossing_count(const Vec3d& origin, const Vec3d& direction, double t_far) const;

private:
    // Traces the ray past every crossing, appending them to `out` unless it is null; returns their number.
    std::size_t traverse(const Vec3d& origin, const Vec3d& direction, double t_far, std::vector<MeshCrossing>* out) const;

    RTCScene scene_ = nullptr;
    // The geometry's own buffers, which the scene keeps alive.
    const Vec3f* positions_;
    const std::array<std::uint32_t, 3>* corners_;
};

}  // namespace isotrace
