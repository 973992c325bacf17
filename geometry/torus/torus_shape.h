#pragma once
// The torus shape: one ring torus (torus.h) as an Embree user geometry of one primitive. Rigid motions and uniform
// scales are baked; other transforms trace it in its own space. It is a closed solid for CSG (a line is
// inside it on up to two spans).
#include "geometry/torus/torus.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

class TorusShape final : public Shape, public Solid {
public:
    explicit TorusShape(const Torus& torus) : torus_(torus) {}

    std::string type_name() const override { return "torus"; }
    // The exact signed distance to the tube.
    std::unique_ptr<ImplicitField> implicit_field() const override;
    std::size_t primitive_count() const override { return 1; }
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    bool can_bake(const Transform& to_world) const override { return to_world.similarity_scale() > 0; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;
    // uv: u the angle around the axis from the reference direction over 2π (counter-clockwise seen from the top),
    // v the angle around the tube over 2π, 0 on the outer equator and ¼ on the top circle; with dpdu and dpdv.
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const override;
    bool has_uv() const override { return true; }

    // Uniform by area: the angle around the axis uniform, the angle around the tube with density ∝ R + r·cos θ.
    bool supports_surface_sampling() const override { return true; }
    SurfaceSample sample_surface(std::array<float, 2> u) const override;
    float surface_area() const override;

    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override;
    bool certainly_outside(const Vec3d& point, double distance) const override;

    const Torus& torus() const { return torus_; }

private:
    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    Torus torus_;
    int counter_slot_ = 0;
};

}  // namespace isotrace
