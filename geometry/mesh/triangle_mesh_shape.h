#pragma once
// Triangle mesh traced natively by Embree. Object transforms are always baked into the vertices. A closed,
// outward-facing mesh is also a Solid for CSG; its inside spans come from a private Embree scene that lists every
// crossing of a ray.
#include <memory>
#include <optional>

#include "geometry/mesh/mesh_crossing_scene.h"
#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"
#include "renderer/sampling/area_distribution.h"

namespace isotrace {

class TriangleMeshShape final : public Shape, public Solid {
public:
    explicit TriangleMeshShape(TriangleMeshData mesh);

    std::string type_name() const override { return "triangle_mesh"; }
    std::unique_ptr<ImplicitField> implicit_field() const override;
    std::size_t primitive_count() const override { return mesh_.triangles.size(); }
    Bounds3f bounds() const override;
    bool can_bake(const Transform&) const override { return true; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;
    // Embree's Ng is (v1-v0)x(v2-v0), the counter-clockwise front, which is what we report.
    LocalShading shading(const RTCHit& hit, const Vec3f& embree_normal, const Vec3d& point) const override;
    // Without vertex normals and uvs a hit's shading is Embree's own (uv swapped after a mirroring bake).
    HitShading hit_shading() const override;
    TriangleView embree_triangles() const override { return {mesh_.positions, mesh_.triangles}; }
    // Meshes with a uv table: a hit's dpdu and dpdv are those of its triangle's affine uv map (zero where the
    // triangle's uvs are collinear).
    bool has_uv() const override { return !mesh_.uvs.empty(); }

    // Uniform by area over all triangles (for area lights): a triangle is picked in proportion to its area,
    // u[0] is rescaled within the picked triangle's share and, with u[1], placed by the low-distortion
    // triangle warp. The normal is the counter-clockwise front, as in shading(). Meshes whose triangles all
    // have zero area (after a degenerate bake) cannot be sampled.
    bool supports_surface_sampling() const override { return areas_.total() > 0; }
    SurfaceSample sample_surface(std::array<float, 2> u) const override;
    float surface_area() const override { return float(areas_.total()); }

    // "triangle_mesh has 6 boundary edges (e.g. 3–7)" and the like (see closed_mesh_problem), or empty.
    std::string solid_problem() const override;
    void prepare_span_queries(RTCDevice device) override;
    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;
    bool exact_boundaries() const override { return false; }  // Embree finds the crossings in float

    const TriangleMeshData& data() const { return mesh_; }

private:
    struct UvDerivatives {
        Vec3f dpdu, dpdv;
    };
    UvDerivatives uv_derivatives(const std::array<std::uint32_t, 3>& triangle) const;
    // The area table follows the vertices: built by the constructor and again by bake(), both before
    // rendering starts, so sampling only reads it (thread-safe).
    void build_area_distribution();

    TriangleMeshData mesh_;
    AreaDistribution areas_;  // over triangles
    bool winding_swapped_ = false;  // bake() reversed every triangle (mirroring transform)
    std::unique_ptr<MeshCrossingScene> crossing_scene_;  // built by prepare_span_queries
    Bounds3f span_bounds_;                               // the vertices' bounds, enlarged a little, at that time
};

}  // namespace isotrace
