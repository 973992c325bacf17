#include "geometry/sweep/radius_measurement.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "geometry/mesh/triangle_mesh_shape.h"
#include "renderer/core/ray.h"
#include "renderer/embree/embree_device.h"

namespace isotrace {

RadiusProbe::RadiusProbe(const TriangleMeshData& mesh) {
    TriangleMeshShape shape(mesh);
    scene_ = std::make_unique<MeshCrossingScene>(embree_device(), shape.create_geometry(embree_device()));
    check_embree("building the mesh for radius measurement");
    const MeshBounds b = mesh.bounds();
    reach_ = 4 * length(Vec3d(b.max) - Vec3d(b.min)) + 1;
}

std::vector<double> RadiusProbe::measure(const Vec3d& centre, const Quaternion& orientation, int samples) const {
    // Embree asserts on rays that are not finite in float: refuse them here.
    if (!is_finite(centre) || !orientation.is_finite() || max_component(abs(centre)) > kWorldLimit)
        throw std::invalid_argument("radii: the key section's centre is not finite or too far out (beyond 1e18)");
    std::vector<double> radii;
    std::vector<MeshCrossing> crossings;
    for (int j = 0; j < samples; ++j) {
        double nearest = INFINITY;
        // A ray along a shared edge can slip between its triangles: then two slightly turned rays try again.
        for (const double nudge : {0.0, 1e-5, -1e-5}) {
            const double theta = 2 * std::numbers::pi * j / samples + nudge;
            const Vec3d direction = orientation.rotate({std::cos(theta), std::sin(theta), 0});
            crossings.clear();
            scene_->crossings(centre, direction, reach_, crossings);
            for (const MeshCrossing& c : crossings)
                if (c.t > 0) nearest = std::min(nearest, c.t);
            if (std::isfinite(nearest)) break;
        }
        if (!std::isfinite(nearest)) {
            std::ostringstream problem;
            problem << "radii: the ray at θ = " << 360.0 * j / samples << "° from the centre meets no surface";
            throw std::invalid_argument(problem.str());
        }
        radii.push_back(nearest);
    }
    return radii;
}

}  // namespace isotrace
