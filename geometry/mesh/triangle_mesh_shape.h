#pragma once
// Triangle mesh traced natively by Embree. Object transforms are always baked into the vertices.
#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/plugin/shape.h"

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

private:
    TriangleMeshData mesh_;
    bool winding_swapped_ = false;  // bake() reversed every triangle (mirroring transform)
};

}  // namespace isotrace
