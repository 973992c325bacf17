#pragma once
// The "blobs" shape: a BlobGroup as one Embree user geometry, one primitive per cell (blob_cells.h), bounds =
// the cell's box. A cell's intersect callback reports the first crossing of the summed field within the cell;
// cells are disjoint, so Embree's shrinking t_far makes the nearest of them the hit and culls the cells behind
// it. The callback also stores the hit's normal in Embree's Ng, summed from the elements its sweep holds (a hit
// that a nearer cell later replaces wasted that sum, which is rare); shading() reads it back. As a CSG operand the
// group is a solid: inside is where the summed field exceeds the threshold. Elements may carry materials of their
// own, which blend at a hit by their shares of the field (blob_materials.h); groups without them skip all of that.
#include <array>

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
    void count_work(const BlobQueryWork& work) const;
    // The first crossing in (t_near, t_far) within cell `cell` and its normal, its work counted.
    std::optional<CellHit> first_hit(std::uint32_t cell, const Vec3d& origin, const Vec3d& direction, double t_near,
                                     float t_far) const;
    // Whether any crossing lies in (t_near, t_far) within cell `cell`, its work counted.
    bool occludes(std::uint32_t cell, const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) const;
    // The part with the largest share of the field at a point (CSG shows one material per surface point).
    std::uint32_t largest_part(const Vec3d& point) const;
    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    BlobGroup group_;
    BlobMaterials materials_;
    int counter_slot_ = 0;
    // Counter slots of every BlobQueryWork field for this group ("blobs[name].pieces", ...), each registered to add
    // into the total of all blob groups ("blobs.pieces", ...) when totals are read.
    std::array<int, 10> work_slots_{};
};

}  // namespace isotrace
