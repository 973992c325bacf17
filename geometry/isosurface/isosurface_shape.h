#pragma once
// The "isosurface" shape: the zero set of any ImplicitField f (negative inside) within a container, traced exactly
// without a Lipschitz constant. The container's box is split by an interval octree (interval_octree.h) into the
// cells that may hold the surface, one Embree user primitive each. A ray's segment through a cell is searched with
// the guaranteed crossing search (geometry/field/crossing_search.h): the field's interval over the segment's box
// drops stretches without a root, the interval of its slope along the ray proves a bracket holds one root, and
// Newton steps along the ray (safeguarded by the bracket) refine it to a few ulps. Tangent contacts follow the search's rule: two crossings closer than
// `resolution` (or none) are not reported. The solid is {f < 0} ∩ container, so the container's boundary is
// surface where f < 0 there, and the shape is a closed Solid for CSG.
//
// Work is bounded per ray and primitive: `max_work` field evaluations and bounds; past it the search stops
// subdividing and reports only brackets it already holds (counted as isosurface.budget_exhausted).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/field/crossing_search.h"
#include "geometry/isosurface/cell_fields.h"
#include "geometry/isosurface/container.h"
#include "geometry/isosurface/interval_octree.h"
#include "geometry/isosurface/linear_cell_bound.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

struct IsosurfaceSettings {
    double resolution = 0;  // metres; 0: a millionth of the container's diagonal
    std::uint64_t max_work = 1 << 16;
    OctreeLimits octree;
};

struct IsosurfaceWork {
    CrossingSearchWork search;
    bool budget_exhausted = false;
};

class IsosurfaceShape final : public Shape, public Solid {
public:
    // `cells` from surface_cells(*field, container, ...), `cell_fields` (when given) the field each searches with;
    // `keep_alive` owns whatever the field refers to (the shapes of its field terms).
    IsosurfaceShape(std::shared_ptr<const ImplicitField> field, const Container& container, std::vector<IntervalBox> cells,
                    const IsosurfaceSettings& settings, CellFields cell_fields = {},
                    std::vector<std::unique_ptr<Shape>> keep_alive = {});

    std::string type_name() const override { return "isosurface"; }
    std::size_t primitive_count() const override { return cells_.size(); }
    std::size_t memory_bytes() const override {
        return cells_.capacity() * (sizeof(IntervalBox) + sizeof(LinearCellBound) + 1);
    }
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    // The field is the user's function of the object's own coordinates: any placement is an instance.
    bool can_bake(const Transform& to_world) const override { return to_world.is_identity(); }
    void bake(const Transform& to_world) override { (void)to_world; }
    RTCGeometry create_geometry(RTCDevice device) override;
    HitShading hit_shading() const override { return HitShading::EmbreeHit; }

    // Positive inside: −max(f, container distance).
    std::optional<double> field_value(const Vec3d& point) const override;
    Vec3d field_gradient(const Vec3d& point) const override;
    std::unique_ptr<ImplicitField> implicit_field() const override;

    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;

    // The first surface point of origin + t·direction in (t_near, t_far) within cell `index` (every cell when
    // index is out of range): its t and outward unit normal.
    struct Hit {
        double t;
        Vec3d normal;
    };
    std::optional<Hit> first_hit(std::uint32_t index, const Vec3d& origin, const Vec3d& direction, double t_near,
                                 double t_far, IsosurfaceWork& work) const;

    // Whether the surface crosses origin + t·direction for a t in (t_near, t_far) within cell `index`: first_hit's
    // answer, without refining a crossing whose bracket already lies within the range.
    bool occludes(std::uint32_t index, const Vec3d& origin, const Vec3d& direction, double t_near, float t_far,
                  IsosurfaceWork& work) const;

    const ImplicitField& field() const { return *field_; }
    const Container& container() const { return container_; }
    const std::vector<IntervalBox>& cells() const { return cells_; }

private:
    // Visits the crossings of f along [a, b] (inside the container; g_a and g_b = f there; ranges_a_b, when known,
    // f's intervals over the segment), nearest first, within the work budget.
    // first_hit, or with Bracketed a hit at a crossing whose bracket lies within (t_near, t_far) (t only within
    // the bracket, no normal); `undecided` is set when the first bracket reaches past either end of the range.
    template <CrossingPrecision precision>
    std::optional<Hit> surface_in_cell(std::uint32_t index, const Vec3d& origin, const Vec3d& direction, double t_near,
                                       double t_far, IsosurfaceWork& work, bool& undecided) const;
    template <CrossingPrecision precision = CrossingPrecision::Refined, class Visit>
    void search(const ImplicitField& field, const Vec3d& origin, const Vec3d& direction, double a, double b,
                double g_a, double g_b, std::optional<FieldRanges> ranges_a_b, IsosurfaceWork& work,
                Visit&& visit) const;
    // The outward normal where f crosses zero: its normalised gradient (facing the ray where it has none).
    Vec3d surface_normal(const Vec3d& p, const Vec3d& direction) const;
    void record_work(const IsosurfaceWork& work) const;
    // The field cell `index` searches with (the whole field for an index out of range).
    const ImplicitField& field_of(std::uint32_t index) const {
        return index < cell_fields_.of_cell.size() ? *cell_fields_.fields[cell_fields_.of_cell[index]] : *field_;
    }

    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    std::vector<std::unique_ptr<Shape>> keep_alive_;
    std::shared_ptr<const ImplicitField> field_;
    Container container_;
    std::vector<IntervalBox> cells_;
    std::vector<LinearCellBound> cell_bounds_;  // one per cell
    std::vector<std::uint8_t> within_container_;  // per cell: 1 where it lies inside the container
    CellFields cell_fields_;
    double resolution_;
    std::uint64_t max_work_;
    int counter_slot_ = 0;
    // interval bounds, slope bounds, slope proofs, evaluations, halvings, refined crossings, budget exhausted
    std::array<int, 7> work_slots_{};
};

}  // namespace isotrace
