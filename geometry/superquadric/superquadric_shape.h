#pragma once
// The "superquadric" shape: a set of (deformed) superquadrics as one Embree user geometry, one primitive per
// superquadric with the bound of its deformed box. It is also a Solid, so CSG can combine superquadrics: the
// inside spans are the union of the superquadrics' own spans.
#include <array>
#include <optional>
#include <vector>

#include "geometry/superquadric/superquadric.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

class SuperquadricShape final : public Shape, public Solid {
public:
    explicit SuperquadricShape(std::vector<Superquadric> superquadrics);

    std::string type_name() const override { return "superquadric"; }
    std::unique_ptr<ImplicitField> implicit_field() const override;
    std::size_t primitive_count() const override { return superquadrics_.size(); }
    std::size_t memory_bytes() const override;
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    // Similarities keep the tolerances (relative to the object's size) meaningful; other maps are instanced.
    bool can_bake(const Transform& to_world) const override { return to_world.similarity_scale() > 0; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;

    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;
    // Span ends carry no normal: a normal (logarithms and powers, the deformation's Jacobians) costs about as much
    // as finding the end, and a CSG shows one of the ends it asks for.
    bool defers_normals(std::uint32_t) const override { return true; }
    Vec3d boundary_normal(const Vec3d& origin, const Vec3d& direction, const BoundaryPoint& end) const override;
    bool certainly_outside(const Vec3d& point, double distance) const override;
    // One superquadric: its first crossing when the ray enters there, and a point past it that the ray is shown to
    // reach inside (Superquadric::inside_after_entry), without searching on to its exit.
    LeadingSpan leading_span(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                             QueryScratch& scratch) const override;

    // The field of the union, positive inside: max over the set of 1 − G(D⁻¹(P)), G the superellipsoid's gauge
    // (superellipsoid.h: homogeneous of degree one, so 1 − G is about the depth below the surface in units of the
    // semi-axis) at the undeformed point, deformed ones included (their inverse chain is exact and cheap). Beyond
    // a superquadric's deformed box it goes on falling with the distance to the box (Superquadric::continued_field).
    std::optional<double> field_value(const Vec3d& point) const override;
    // Along the analytic normal of the superquadric whose field is the largest, the field's slope in that direction
    // (a central difference of a millionth of the set's size): exact in direction, and where the gauge has no
    // gradient (creases, poles) still the normal the surface is shaded with.
    Vec3d field_gradient(const Vec3d& point) const override;

    const std::vector<Superquadric>& superquadrics() const { return superquadrics_; }

private:
    // The spans of one superquadric (primitive `index`), in order; `found` holds its crossings on the way.
    void primitive_spans(std::uint32_t index, const Vec3d& origin, const Vec3d& direction, double t_min,
                         double t_max, std::vector<InsideSpan>& spans, std::vector<Crossing>& found) const;
    void record_work(const SuperquadricWork& work) const;
    // Superquadric `index`'s first crossing in (t_near, t_far), its work recorded.
    std::optional<double> first_hit(std::uint32_t index, const Vec3d& origin, const Vec3d& direction, double t_near,
                                    float t_far) const;
    // Whether superquadric `index` of the shape `self` blocks the ray (an occlusion query), its work recorded; also
    // what a query put off by the first pass of a two-pass occlusion query is asked (PutOffQuery::Ask).
    static bool blocks(const void* self, std::uint32_t index, const Vec3d& origin, const Vec3d& direction,
                       double t_near, float t_far);

    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    // The superquadric with the smallest continued field at the point (the one whose inside it is deepest in).
    const Superquadric& deepest(const Vec3d& point) const;
    void measure_field_step();

    std::vector<Superquadric> superquadrics_;
    double field_step_ = 0;  // field_gradient's step: a millionth of the largest extent of the set's bounding box
    int counter_slot_ = 0;
    // interval bounds, slope bounds, slope proofs, evaluations, halvings, refined crossings, quadratic solves
    std::array<int, 7> work_slots_{};
};

}  // namespace isotrace
