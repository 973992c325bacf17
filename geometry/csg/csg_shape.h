#pragma once
// Constructive solid geometry traced exactly: one Embree primitive per CSG tree, whose intersect callback asks
// every child for its inside spans along the ray and combines them by Roth's classification
// (span_combination.h). The shape is itself a Solid, so trees nest.
//
// Parts: every leaf solid of the tree is a part, numbered depth-first; a hit's part (LocalShading::part, carried
// in Embree's primID) names the leaf surface that bounds the result there, and with it the child's material.
#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/csg/solid_user_geometry.h"
#include "geometry/csg/span_combination.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

// A child as the scene describes it: a shape that is a closed solid, its placement in the CSG's space, and the
// material its surfaces show (empty name: the parent's).
struct CsgChild {
    std::unique_ptr<Shape> shape;
    Transform to_csg;
    MaterialReference material;
};

class CsgShape final : public Shape, public Solid {
public:
    // Throws std::invalid_argument for an empty list or a child that is not a Solid. Whether a child really
    // encloses a volume (solid_problem()) is the caller's to check: the scene plugin reports it at the child.
    CsgShape(CsgOperation operation, std::vector<CsgChild> children);

    std::string type_name() const override { return "csg"; }
    std::unique_ptr<ImplicitField> implicit_field() const override;
    std::size_t primitive_count() const override { return 1; }
    std::size_t memory_bytes() const override;
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    // Always: children bake the transform when they can and keep it (mapping rays) when they cannot.
    bool can_bake(const Transform&) const override { return true; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const override;
    std::vector<MaterialReference> part_materials() const override;

    void prepare_span_queries(RTCDevice device) override;
    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;
    // A difference whose first operand's entry lies certainly outside every subtracted operand takes that entry
    // without asking the others for their spans (csg_first_surface_point.cpp).
    std::optional<BoundaryPoint> first_surface_point(const Vec3d& origin, const Vec3d& direction, double t_near,
                                                     double t_far, QueryScratch& scratch) const override;
    // A union's first span from its operands in the order the ray reaches their bounds, stopping at the first
    // operand whose bounds begin clear of the span found (csg_leading_span.cpp).
    LeadingSpan leading_span(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                             QueryScratch& scratch) const override;
    bool certainly_outside(const Vec3d& point, double distance) const override;
    bool exact_boundaries() const override { return exact_boundaries_; }
    // A part's ends defer their normal when its leaf does; boundary_normal asks the leaf and carries the answer up.
    bool defers_normals(std::uint32_t part) const override;
    Vec3d boundary_normal(const Vec3d& origin, const Vec3d& direction, const BoundaryPoint& end) const override;

    CsgOperation operation() const { return operation_; }
    std::size_t operand_count() const { return operands_.size(); }
    const Shape& operand(std::size_t index) const { return *operands_[index].shape; }
    // Operand `index`'s placement in the CSG's space when it could not be baked into the operand.
    const std::optional<Transform>& operand_placement(std::size_t index) const { return operands_[index].to_csg; }

private:
    struct Operand {
        std::unique_ptr<Shape> shape;
        Solid* solid = nullptr;                // the same object as `shape`
        std::optional<Transform> to_csg;       // set when the child cannot bake its placement
        std::optional<Transform> from_csg;     // its inverse
        MaterialReference material;
        std::uint32_t first_part = 0;
        std::uint32_t part_count = 1;
        // Its bounds in the CSG's space, widened beyond their float rounding (set by place): the ray meets none of
        // its spans before it enters them. Empty bounds: lower above upper.
        Vec3d reach_lower, reach_upper;
    };

    // The spans leading_span asked operands for, kept for the span listing of the same tree along the same ray and
    // range at the same depth that may follow it (a leading span that settles nothing is followed by the full
    // spans). The spans are the operands' answers to that ray and range, so a listing kept longer stays right.
    struct Asked {
        const CsgShape* tree = nullptr;  // none kept
        Vec3d origin, direction;
        double t_min = 0, t_max = 0;
        std::vector<bool> kept;  // by operand
        std::vector<std::vector<InsideSpan>> spans;

        bool along(const CsgShape* shape, const Vec3d& o, const Vec3d& d, double t0, double t1) const {
            return tree == shape && origin == o && direction == d && t_min == t0 && t_max == t1;
        }
    };

    // A call's buffers, held while its children (nested trees among them) fill theirs.
    struct Buffers {
        std::vector<InsideSpan> operand_spans;
        std::vector<SpanEvent> events;
        std::vector<InsideSpan> result;  // first_surface_point's spans of the whole
        std::vector<std::pair<double, std::uint32_t>> reached;  // leading_span's operands by where the ray reaches them
        Asked asked;
    };

    void place(Operand& operand, const Transform& to_csg);
    // The index of the operand that holds part `part` (of the tree's parts).
    std::size_t operand_of(std::uint32_t part) const;
    Bounds3f operand_bounds(const Operand& operand) const;
    // The operand's inside spans along a ray given in the CSG's space, with normals and parts in the CSG's terms.
    void operand_spans(const Operand& operand, const Vec3d& origin, const Vec3d& direction, double t_min,
                       double t_max, std::vector<InsideSpan>& spans, QueryScratch& scratch) const;
    // The operand's leading_span, in the CSG's terms as operand_spans gives its spans.
    LeadingSpan operand_leading_span(const Operand& operand, const Vec3d& origin, const Vec3d& direction, double t_min,
                                     double t_max, QueryScratch& scratch) const;
    // Operand `index`'s spans as operand_spans gives them: those `asked` kept (when it holds them for this ray and
    // range), else asked now.
    void operand_spans(std::uint32_t index, const Asked* asked, const Vec3d& origin, const Vec3d& direction,
                       double t_min, double t_max, std::vector<InsideSpan>& spans, QueryScratch& scratch) const;
    // inside_spans, once the first operand's spans are in `operand_buffer` (which then takes the others' in turn);
    // `asked` as for operand_spans.
    void combine_with_first(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                            std::vector<InsideSpan>& operand_buffer, std::vector<SpanEvent>& events,
                            std::vector<InsideSpan>& spans, const Asked* asked, QueryScratch& scratch) const;
    static bool operand_certainly_outside(const Operand& operand, const Vec3d& point, double distance);

    CsgOperation operation_;
    std::vector<Operand> operands_;
    std::uint32_t part_count_ = 0;
    bool exact_boundaries_ = true;
    SolidUserGeometry geometry_;
    std::array<int, 2> span_slots_{};  // span combinations, span events
};

}  // namespace isotrace
