// The implicit field of a closed triangle mesh: the signed distance, |p − q| to the closest point q on the
// triangles (Embree point query over the mesh's BVH) with the sign by ray parity — the majority of three rays in
// fixed, unrelated directions, so that a ray grazing an edge or a vertex cannot flip it. Negative inside.
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "geometry/mesh/closest_triangle_point.h"
#include "geometry/mesh/mesh_closedness.h"
#include "geometry/mesh/mesh_crossing_scene.h"
#include "geometry/mesh/triangle_mesh_shape.h"
#include "renderer/embree/embree_device.h"

namespace isotrace {
namespace {

class MeshDistanceField final : public ImplicitField {
public:
    explicit MeshDistanceField(const TriangleMeshShape& shape) : copy_(shape.data()), nearest_(copy_.data()) {
        const std::string problem = closed_mesh_problem(copy_.data());
        if (!problem.empty()) throw std::invalid_argument("the mesh " + problem + ": it has no inside");
        RTCDevice device = embree_device();
        crossings_ = std::make_unique<MeshCrossingScene>(device, copy_.create_geometry(device));
        check_embree("mesh distance field");
        const MeshBounds b = copy_.data().bounds();
        bounds_ = {Vec3d(b.min), Vec3d(b.max)};
    }

    double value(const Vec3d& p) const override {
        const double d = nearest_.nearest(p, INFINITY).distance;
        return inside(p) ? -d : d;
    }
    Vec3d gradient(const Vec3d& p) const override {
        const ClosestTrianglePoint q = nearest_.nearest(p, INFINITY);
        const double sign = inside(p) ? -1 : 1;
        if (q.distance > 1e-9 * (1 + length(p))) return (p - q.point) * (sign / q.distance);
        return nearest_.triangle_normal(q.triangle);  // on the surface: the triangle's outward normal
    }
    FieldBox bounds() const override { return bounds_; }
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return nearest_.nearest(centre, radius).found();
    }

private:
    bool inside(const Vec3d& p) const {
        static constexpr std::array<Vec3d, 3> kDirections = {Vec3d{0.5773, 0.6164, 0.5354}, Vec3d{-0.7071, 0.1316, 0.6947},
                                                             Vec3d{0.2104, -0.8847, -0.4160}};
        int votes = 0;
        for (const Vec3d& d : kDirections) votes += int(crossings_->crossing_count(p, d, INFINITY) % 2);
        return votes >= 2;
    }

    TriangleMeshShape copy_;  // the mesh, for the Embree geometries
    ClosestPointQuery nearest_;
    std::unique_ptr<MeshCrossingScene> crossings_;
    FieldBox bounds_;
};

}  // namespace

std::unique_ptr<ImplicitField> TriangleMeshShape::implicit_field() const { return std::make_unique<MeshDistanceField>(*this); }

}  // namespace isotrace
