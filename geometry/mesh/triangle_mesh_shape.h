#pragma once
// Triangle mesh traced natively by Embree. Object transforms are always baked into the vertices.
#include <optional>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/plugin/shape.h"
#include "renderer/sampling/distribution_1d.h"

namespace isotrace {

class TriangleMeshShape final : public Shape {
public:
    explicit TriangleMeshShape(TriangleMeshData mesh);

    std::string type_name() const override { return "triangle_mesh"; }
    std::size_t primitive_count() const override { return mesh_.triangles.size(); }
    Bounds3f bounds() const override;
    bool can_bake(const Transform&) const override { return true; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;
    // Embree's Ng is (v1-v0)x(v2-v0), the counter-clockwise front, which is what we report.
    LocalShading shading(const RTCHit& hit, const Vec3f& embree_normal) const override;

    // Uniform by area over all triangles (for area lights): a triangle is picked in proportion to its area,
    // u[0] is rescaled within the picked triangle's share and, with u[1], placed by the low-distortion
    // triangle warp. The normal is the counter-clockwise front, as in shading(). Meshes whose triangles all
    // have zero area (after a degenerate bake) cannot be sampled.
    bool supports_surface_sampling() const override { return total_area_ > 0; }
    SurfaceSample sample_surface(std::array<float, 2> u) const override;
    float surface_area() const override { return float(total_area_); }

private:
    // The area table follows the vertices: built by the constructor and again by bake(), both before
    // rendering starts, so sampling only reads it (thread-safe).
    void build_area_distribution();

    TriangleMeshData mesh_;
    std::optional<Distribution1D> area_distribution_;  // over triangles, by area
    double total_area_ = 0;
    bool winding_swapped_ = false;  // bake() reversed every triangle (mirroring transform)
};

}  // namespace isotrace
