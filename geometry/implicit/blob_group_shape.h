#pragma once
// The "blobs" shape: a BlobGroup as one Embree user geometry, one primitive per cell (blob_cells.h), bounds =
// the cell's box. Its intersect and occluded callbacks are those of the build of the cell queries the group chose
// (blob_ray.cpp, blob_cell_queries.h); a hit's normal is stored in Embree's Ng, and shading() reads it back. As a CSG
// operand the group is a solid: inside is where the summed field exceeds the threshold. Elements may carry materials
// of their own, which blend at a hit by their shares of the field (blob_materials.h); groups without them skip all
// of that.

#include "geometry/implicit/blob_cell_queries.h"
#include "geometry/implicit/blob_group.h"
#include "geometry/implicit/blob_materials.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

class BlobGroupShape final : public Shape, public Solid {
public:
    // Throws std::invalid_argument when `materials` has parts for another number of elements.
    explicit BlobGroupShape(BlobGroup group, BlobMaterials materials = {});

    std::string type_name() const override { return "blobs"; }
    std::unique_ptr<ImplicitField> implicit_field() const override;
    // Elements, as the user counts them (Embree sees the cells: blob_cells.h).
    std::size_t primitive_count() const override { return group_.elements().size(); }
    std::size_t memory_bytes() const override { return group_.memory_bytes() + materials_.memory_bytes(); }
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    bool can_bake(const Transform& to_world) const override { return to_world.similarity_scale() > 0; }
    void bake(const Transform& to_world) override {
        if (!to_world.is_identity()) group_.bake(to_world, to_world.similarity_scale());
    }
    RTCGeometry create_geometry(RTCDevice device) override;
    // With element materials: the blend at the point, and as the part its largest share.
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const override;
    std::vector<MaterialReference> part_materials() const override { return materials_.parts(); }
    bool blends_parts() const override { return !materials_.empty(); }
    // F(P) = Σ wᵢ·fᵢ(P) − T, positive inside, and its gradient (zero on a hard cube's step: metacube.h).
    std::optional<double> field_value(const Vec3d& point) const override;
    Vec3d field_gradient(const Vec3d& point) const override;

    void prepare_span_queries(RTCDevice) override { register_counters(); }
    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;

    const BlobGroup& group() const { return group_; }
    const BlobMaterials& materials() const { return materials_; }

private:
    void register_counters();
    // The part with the largest share of the field at a point (CSG shows one material per surface point).
    std::uint32_t largest_part(const Vec3d& point) const;
    static void bounds_callback(const RTCBoundsFunctionArguments* args);

    BlobGroup group_;
    BlobMaterials materials_;
    // What the Embree callbacks read (their user data), with the counters of this group's work.
    BlobRayTarget target_;
};

}  // namespace isotrace
