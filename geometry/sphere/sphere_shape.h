#pragma once
// Analytic spheres as one Embree user geometry (one primitive per sphere). This is the pattern every
// implicit primitive follows: per-primitive bounds, intersect/occluded callbacks that accept a root only in
// (t_near, t_far) and count their tests for the statistics. As a Solid (for CSG) a set of spheres is their union.
#include <optional>
#include <vector>

#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"
#include "renderer/sampling/area_distribution.h"

namespace isotrace {

struct Sphere {
    Vec3d centre;
    double radius = 1;
};

class SphereShape final : public Shape, public Solid {
public:
    explicit SphereShape(std::vector<Sphere> spheres);

    std::string type_name() const override { return "sphere"; }
    std::unique_ptr<ImplicitField> implicit_field() const override;
    std::size_t primitive_count() const override { return spheres_.size(); }
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    bool can_bake(const Transform& to_world) const override { return to_world.similarity_scale() > 0; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;
    // uv: spherical coordinates about the y axis (see shading()), with their analytic dpdu and dpdv.
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const override;
    bool has_uv() const override { return true; }

    // Uniform by area over all spheres (for area lights): a sphere is picked in proportion to its area, u[0]
    // is rescaled within its share, and the point is uniform on it with the outward normal. The area table is
    // built by the constructor and again by bake(), before rendering, so sampling only reads it.
    bool supports_surface_sampling() const override { return areas_.total() > 0; }
    SurfaceSample sample_surface(std::array<float, 2> u) const override;
    float surface_area() const override { return float(areas_.total()); }

    const std::vector<Sphere>& spheres() const { return spheres_; }

    // Closed form per sphere; overlapping spheres of one set merge (their union is the solid).
    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;
    bool certainly_outside(const Vec3d& point, double distance) const override;

private:
    void build_area_distribution();
    // The span of the line inside sphere `index` (unclipped), unless the line misses or only touches it.
    std::optional<InsideSpan> span_of(std::uint32_t index, const Vec3d& origin, const Vec3d& direction) const;

    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    std::vector<Sphere> spheres_;
    AreaDistribution areas_;  // over spheres
    int counter_slot_ = 0;
};

}  // namespace isotrace
