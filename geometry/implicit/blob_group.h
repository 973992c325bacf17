#pragma once
// BlobGroup: skeletal elements (metaballs and metacubes) whose fields add up, and the surface where the sum
// reaches the group's threshold: F(P) = Σ wᵢ·fᵢ(dist²ᵢ(P)) − T = 0, outward normal −∇F.
//
// Ray queries work per element, as Embree calls them: along element i's support interval the ray is cut at every
// breakpoint of i and of its neighbours (support entry/exit, metacube region planes, kernel piece boundaries);
// on each piece every active element's field is a polynomial in t (or, for non-polynomial kernels, a function
// with a known Lipschitz bound), the pieces are searched in order and the first crossing is returned. Every
// crossing lies in some element's support, so the nearest over all elements (Embree's shrinking t_far) is the
// nearest hit. Neighbour lists (elements whose supports overlap) are built once.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/implicit/field_function.h"
#include "geometry/implicit/metacube.h"
#include "renderer/math/transform.h"

namespace isotrace {

// Work done by ray queries, for the statistics.
struct BlobQueryWork {
    std::uint64_t pieces = 0;        // ray pieces examined
    std::uint64_t polynomial_solves = 0;
    std::uint64_t lipschitz_searches = 0;
    std::uint64_t roots = 0;         // crossings reported
};

class BlobGroup {
public:
    // Throws std::invalid_argument (field "threshold") for a threshold that is not finite and > 0.
    BlobGroup(std::vector<Metacube> elements, std::unique_ptr<const FieldFunction> kernel, double threshold);

    const std::vector<Metacube>& elements() const { return elements_; }
    const FieldFunction& kernel() const { return *kernel_; }
    double threshold() const { return threshold_; }
    const std::vector<std::uint32_t>& neighbours(std::size_t index) const { return neighbours_[index]; }
    std::size_t memory_bytes() const;
    std::uint64_t identity() const { return identity_; }

    // The first t in (t_min, t_max) within element `index`'s support where F changes sign along o + t·d.
    std::optional<double> first_crossing(std::size_t index, const Vec3d& origin, const Vec3d& direction, double t_min,
                                         double t_max, BlobQueryWork& work) const;

    // F(P) + T (the summed field) and its gradient, from element `index` and its neighbours (which include every
    // element whose field is non-zero anywhere in element `index`'s support).
    double field(std::size_t index, const Vec3d& point) const;
    Vec3d gradient(std::size_t index, const Vec3d& point) const;

    // Outward unit normal at a surface point found through element `index`: −∇F, or for hard cubes (whose field
    // is a step) the normal of the nearest face of the hard cube that contains the point on its boundary.
    Vec3d normal(std::size_t index, const Vec3d& point) const;

    // Applies a similarity transform (rotation, uniform scale, translation; `scale` is its scale factor).
    void bake(const Transform& similarity, double scale);

private:
    void build_neighbours();

    std::vector<Metacube> elements_;
    std::unique_ptr<const FieldFunction> kernel_;
    double threshold_;
    std::vector<std::vector<std::uint32_t>> neighbours_;
    std::uint64_t identity_;  // unique per group and per geometry change, for the per-ray slice cache
};

}  // namespace isotrace
