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
    std::size_t primitive_count() const override { return superquadrics_.size(); }
    std::size_t memory_bytes() const override;
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    // Similarities keep the tolerances (relative to the object's size) meaningful; other maps are instanced.
    bool can_bake(const Transform& to_world) const override { return to_world.similarity_scale() > 0; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;

    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans) const override;

    const std::vector<Superquadric>& superquadrics() const { return superquadrics_; }

private:
    // The spans of one superquadric (primitive `index`), in order.
    void primitive_spans(std::uint32_t index, const Vec3d& origin, const Vec3d& direction, double t_min,
                         double t_max, std::vector<InsideSpan>& spans) const;
    void record_work(const SuperquadricWork& work) const;
    // Superquadric `index`'s first crossing in (t_near, t_far), its work recorded.
    std::optional<double> first_hit(std::uint32_t index, const Vec3d& origin, const Vec3d& direction, double t_near,
                                    float t_far) const;

    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    std::vector<Superquadric> superquadrics_;
    int counter_slot_ = 0;
    // interval bounds, slope bounds, monotone proofs, evaluations, halvings, refined crossings, polynomial solves
    std::array<int, 7> work_slots_{};
};

}  // namespace isotrace
