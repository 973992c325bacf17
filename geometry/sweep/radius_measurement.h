#pragma once
// Radii of a key section measured from a mesh: rays from the section's centre in its plane, at θ_j = 2πj/m in
// its local frame, traced through Embree (every crossing listed, the nearest one taken).
#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh/mesh_crossing_scene.h"
#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/math/quaternion.h"

namespace isotrace {

class RadiusProbe {
public:
    explicit RadiusProbe(const TriangleMeshData& mesh);

    // Throws std::invalid_argument "radii: the ray at θ = …° from the centre meets no surface" when a ray hits
    // nothing (the section is not inside the mesh).
    std::vector<double> measure(const Vec3d& centre, const Quaternion& orientation, int samples) const;

private:
    std::unique_ptr<MeshCrossingScene> scene_;
    double reach_;  // longer than any ray inside the mesh's bounds
};

}  // namespace isotrace
