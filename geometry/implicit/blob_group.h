#pragma once
// BlobGroup: skeletal elements (metaballs and metacubes) whose fields add up, and the surface where the sum
// reaches the group's threshold: F(P) = Σ wᵢ·fᵢ(dist²ᵢ(P)) − T = 0, outward normal −∇F.
//
// Ray queries work per element, as Embree calls them: along element i's support interval the summed field of i
// and its neighbours is searched piece by piece (field_along_ray.h) and the first crossing is returned. Every
// crossing lies in some element's support, so the nearest over all elements (Embree's shrinking t_far) is the
// nearest hit. The elements near a stretch of ray or a point come from a compact hierarchy over the supports
// (element_bvh.h); what one query learns about a ray is kept for the next element's query of the same ray
// (blob_ray_cache.h).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/implicit/element_bvh.h"
#include "geometry/implicit/field_along_ray.h"
#include "geometry/implicit/field_function.h"
#include "geometry/implicit/metacube.h"
#include "renderer/math/transform.h"

namespace isotrace {

class BlobGroup {
public:
    // Throws std::invalid_argument (field "threshold") for a threshold that is not finite and > 0.
    BlobGroup(std::vector<Metacube> elements, std::unique_ptr<const FieldFunction> kernel, double threshold);

    const std::vector<Metacube>& elements() const { return elements_; }
    const FieldFunction& kernel() const { return *kernel_; }
    double threshold() const { return threshold_; }
    std::size_t memory_bytes() const;
    std::uint64_t identity() const { return identity_; }

    // The first t in (t_min, t_max) within element `index`'s support where F changes sign along o + t·d.
    std::optional<double> first_crossing(std::size_t index, const Vec3d& origin, const Vec3d& direction, double t_min,
                                         double t_max, BlobQueryWork& work) const;

    // Every crossing along o + t·d for t in (t_min, t_max) (finite), in increasing t, from all elements; returns
    // the sign of F at t_min (+1 inside). For CSG.
    int crossings(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                  std::vector<FieldCrossing>& out, BlobQueryWork& work) const;

    // F(P) + T (the summed field) and its gradient.
    double field(const Vec3d& point) const;
    Vec3d gradient(const Vec3d& point) const;

    // Outward unit normal at a surface point: −∇F, or for hard cubes (whose field is a step) the normal of the
    // nearest face of a hard cube that contains the point on its boundary.
    Vec3d normal(const Vec3d& point) const;

    // Applies a similarity transform (rotation, uniform scale, translation; `scale` is its scale factor).
    void bake(const Transform& similarity, double scale);

private:
    void build_index();

    std::vector<Metacube> elements_;
    std::unique_ptr<const FieldFunction> kernel_;
    double threshold_;
    ElementBvh bvh_;
    std::uint64_t identity_;  // unique per group and per geometry change, for the per-ray slice cache
};

}  // namespace isotrace
