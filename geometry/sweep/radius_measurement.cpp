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
    struct Nearest {
        double t = INFINITY;
        bool on_edge = false;
    };
    const auto nearest_at = [&](double theta) {
        const Vec3d direction = orientation.rotate({std::cos(theta), std::sin(theta), 0});
        crossings.clear();
        scene_->crossings(centre, direction, reach_, crossings);
        Nearest found;
        for (const MeshCrossing& c : crossings)
            if (c.t > 0 && c.t < found.t) found = {c.t, c.on_edge};
        return found;
    };
    constexpr double kTurn = 1e-5;  // radians
    for (int j = 0; j < samples; ++j) {
        const double theta = 2 * std::numbers::pi * j / samples;
        const Nearest straight = nearest_at(theta);
        double nearest = straight.t;
        // A ray along a shared edge can slip between its triangles; one whose nearest crossing lies on an edge meets
        // there what rounding decides (a corner that only touches the plane, the rim of an open part). Rays turned a
        // little either way decide instead: the first that crosses, for a ray that slipped through; for an edge,
        // its own distance where a turned ray finds the surface going on through it, else the turned rays' nearest.
        if (!std::isfinite(straight.t) || straight.on_edge) {
            const Nearest turned[2] = {nearest_at(theta + kTurn), nearest_at(theta - kTurn)};
            const auto continues = [&](const Nearest& n) { return std::abs(n.t - straight.t) <= 1e-3 * straight.t; };
            const double nearest_turned = std::min(turned[0].t, turned[1].t);
            if (!std::isfinite(straight.t))
                nearest = std::isfinite(turned[0].t) ? turned[0].t : turned[1].t;
            else if (!continues(turned[0]) && !continues(turned[1]) && std::isfinite(nearest_turned))
                nearest = nearest_turned;
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
