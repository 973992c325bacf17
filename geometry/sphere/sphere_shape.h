#pragma once
// Analytic spheres as one Embree user geometry (one primitive per sphere). This is the pattern every
// implicit primitive follows: per-primitive bounds, intersect/occluded callbacks that accept a root only in
// (t_near, t_far) and count their tests for the statistics.
#include <vector>

#include "renderer/plugin/shape.h"

namespace isotrace {

struct Sphere {
    Vec3d centre;
    double radius = 1;
};

class SphereShape final : public Shape {
public:
    explicit SphereShape(std::vector<Sphere> spheres);

    std::string type_name() const override { return "sphere"; }
    std::size_t primitive_count() const override { return spheres_.size(); }
    Bounds3f bounds() const override;
    bool counts_intersection_tests() const override { return true; }
    bool can_bake(const Transform& to_world) const override { return to_world.similarity_scale() > 0; }
    void bake(const Transform& to_world) override;
    RTCGeometry create_geometry(RTCDevice device) override;
    LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal) const override;

    const std::vector<Sphere>& spheres() const { return spheres_; }

private:
    static void bounds_callback(const RTCBoundsFunctionArguments* args);
    static void intersect_callback(const RTCIntersectFunctionNArguments* args);
    static void occluded_callback(const RTCOccludedFunctionNArguments* args);

    std::vector<Sphere> spheres_;
    int counter_slot_ = 0;
};

}  // namespace isotrace
