#pragma once
// The cylinder and cone shapes: one frustum (frustum.h) as an Embree user geometry of one primitive, its hits'
// primID naming the part (side, base cap, top cap) for shading. Rigid motions and uniform scales are baked into
// the frustum; other transforms trace it in its own space. Capped, it is a closed convex solid for CSG; open,
// it is the side alone and no solid.
#include <string>

#include "geometry/cone/frustum.h"
#include "renderer/params/scene_node.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"
#include "renderer/sampling/area_distribution.h"

namespace isotrace {

class FrustumShape final : public Shape, public Solid {
public:
    // `type` is the plugin's name ("cylinder", "cone"), for statistics and messages.
    FrustumShape(std::string type, const Frustum& frustum);

    std::string type_name() const override { return type_; }
    // The exact signed distance of the capped frustum; throws std::invalid_argument for an open one.
    std::unique_ptr<ImplicitField> implicit_field() const override;
    std::size_t primitive_count() const override { return 1; }
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    bool can_bake(const Transform& to_world) const override { return to_world.similarity_scale() > 0; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;
    // uv on the side: u the angle around the axis from the reference direction (counter-clockwise seen from the
    // top) over 2π, v from the base rim (0) to the top rim (1); on a cap: the same u, v from the centre (0) to the
    // rim (1). With their analytic dpdu and dpdv.
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const override;
    bool has_uv() const override { return true; }

    // Uniform by area over the side and the caps (each picked in proportion to its area).
    bool supports_surface_sampling() const override { return areas_.total() > 0; }
    SurfaceSample sample_surface(std::array<float, 2> u) const override;
    float surface_area() const override { return float(areas_.total()); }

    std::string solid_problem() const override;
    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;
    bool certainly_outside(const Vec3d& point, double distance) const override;

    const Frustum& frustum() const { return frustum_; }

private:
    void build_area_distribution();
    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    std::string type_;
    Frustum frustum_;
    AreaDistribution areas_;  // over the parts, indexed by FrustumPart
    int counter_slot_ = 0;
};

// A frustum from its two end points and radii as a scene gives them, checked: the axis must have a length, the
// shape must lie within the world limit. Errors are reported at `node`'s key `top_key` (the axis) or at the node.
Frustum frustum_from_end_points(const SceneNode& node, const std::string& top_key, const Vec3d& base, const Vec3d& top,
                                double base_radius, double top_radius, bool caps);

}  // namespace isotrace
