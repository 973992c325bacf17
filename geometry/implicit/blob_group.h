#pragma once
// BlobGroup: skeletal elements (metaballs and metacubes) whose fields add up, and the surface where the sum
// reaches the group's threshold: F(P) = Σ wᵢ·fᵢ(dist²ᵢ(P)) − T = 0, outward normal −∇F.
//
// Ray queries work per cell (blob_cells.h): space is cut into disjoint boxes, each listing the elements that
// reach into it, and a cell's stretch of a ray is swept once, front to back (metaball_sweep.h for metaballs of a
// one-piece polynomial kernel, field_sweep.h for everything else), by the cell queries of blob_cell_sweep.cpp, built
// for baseline x86-64 and for AVX2 (blob_cell_queries.h). Cells are what Embree traverses (blob_group_shape.h);
// walking a ray's cells in order gives every crossing (CSG) or the first.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/implicit/blob_cell_queries.h"
#include "geometry/implicit/blob_cells.h"
#include "geometry/implicit/field_function.h"
#include "geometry/implicit/field_sweep.h"
#include "geometry/implicit/metaball_sweep.h"
#include "geometry/implicit/metacube.h"
#include "renderer/math/transform.h"

namespace isotrace {

// A cell's first crossing, with the outward unit normal at the point where a renderer places it.
struct CellHit {
    FieldCrossing crossing;
    // At o + d·float(t) (Embree keeps a hit's t as a float, and the shading point is computed from it); std::nullopt
    // where −∇F vanishes there (a hard cube's face: normal_in_cell takes the face's normal).
    std::optional<Vec3d> normal;
};

class BlobGroup {
public:
    // Throws std::invalid_argument (field "threshold") for a threshold that is not finite and > 0.
    BlobGroup(std::vector<Metacube> elements, std::unique_ptr<const FieldFunction> kernel, double threshold);

    const std::vector<Metacube>& elements() const { return elements_; }
    const FieldFunction& kernel() const { return *kernel_; }
    double threshold() const { return threshold_; }
    const BlobCells& cells() const { return cells_; }
    std::size_t memory_bytes() const;
    // Peak memory per element while a group is generated and built (the element list, the bounding spheres, the
    // cells' lists and kd-tree, Embree's BVH over the cells and the builders' temporaries): the slope of peak RSS
    // of `isotrace info` between generated groups of 10^5 and 10^6 elements at the benchmark scenes' density
    // (docs/reliability.md). The memory budget is charged with it before a "generate" allocates.
    static constexpr std::uint64_t kPeakBytesPerElement = 328;

    // The first crossing of F along o + t·d with t in (t_min, t_max) inside cell `cell` (Embree's query), and its
    // normal, summed from the sweep's own elements (candidate hits are nearly all accepted: 31,330 crossings for
    // 31,302 hits on blobs_10k at 320×180, so a normal per crossing costs less than a second search of the cell).
    std::optional<CellHit> first_crossing_in_cell(std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                                                  double t_min, double t_max, BlobQueryWork& work) const;
    // Whether F crosses T anywhere along o + t·d with t in (t_min, t_max) inside cell `cell` (Embree's occlusion
    // query). A cell that starts inside the surface after a ray start outside it ends at once: the ray crossed the
    // surface before the cell (shadow rays meet cells in the order of Embree's hierarchy, not along the ray, and
    // sweeping the inside of a blob to its far side was most of their work).
    bool occluded_in_cell(std::uint32_t cell, const Vec3d& origin, const Vec3d& direction, double t_min,
                          double t_max, BlobQueryWork& work) const;
    // The first crossing along the whole ray, walking its cells in order.
    std::optional<FieldCrossing> first_crossing(const Vec3d& origin, const Vec3d& direction, double t_min,
                                                double t_max, BlobQueryWork& work) const;
    // Every crossing along o + t·d for t in (t_min, t_max) (finite), in increasing t; returns the sign of F at
    // t_min (+1 inside). For CSG.
    int crossings(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                  std::vector<FieldCrossing>& out, BlobQueryWork& work) const;

    // F(P) + T (the summed field) and its gradient.
    double field(const Vec3d& point) const;
    Vec3d gradient(const Vec3d& point) const;
    // Calls visit(j, wⱼ·fⱼ(P)) for each of the `listed` elements (a cell's, or those near the point) whose support
    // may contain P, in list order: the terms of the field, for those who share it out.
    void for_each_term(std::span<const std::uint32_t> listed, const Vec3d& point,
                       const std::function<void(std::uint32_t element, double term)>& visit) const;

    // Outward unit normal at a surface point: −∇F, or for hard cubes (whose field is a step) the normal of the
    // nearest face of a hard cube that contains the point on its boundary. The cell variant sums the elements
    // of the cell the point lies in (a hit's primitive), skipping the point location.
    Vec3d normal(const Vec3d& point) const;
    Vec3d normal_in_cell(std::uint32_t cell, const Vec3d& point) const;

    // Applies a similarity transform (rotation, uniform scale, translation; `scale` is its scale factor).
    void bake(const Transform& similarity, double scale);

private:
    template <BlobIsa>
    friend class BlobCellSweep;  // the cell queries' sweeps, one build per instruction set

    void build_index();
    enum class KernelKind { Blinn, Nishimura, Murakami, Wyvill, Kim };
    // Calls f with the kernel as its concrete class, so that the sweep's kernel calls are direct
    // (blob_group_with_kernel.h).
    template <class F>
    decltype(auto) with_kernel(F&& f) const;
    Vec3d normal_from(std::span<const std::uint32_t> near, const Vec3d& point) const;
    // ∇(F + T) from the `near` elements (a list that holds every element whose support contains the point).
    Vec3d gradient_from(std::span<const std::uint32_t> near, const Vec3d& point) const;
    // Calls visit(element) for the `listed` elements whose support may contain the point, in list order.
    template <class Visit>
    void for_each_reaching(std::span<const std::uint32_t> listed, const Vec3d& point, Visit&& visit) const;

    std::vector<Metacube> elements_;
    std::unique_ptr<const FieldFunction> kernel_;
    KernelKind kernel_kind_;
    double threshold_;
    std::vector<BoundingSphere> spheres_;  // per element, for the sweep's first test
    double centre_bound_ = 0;              // the largest |centre| of spheres_ (scales that test's float margin)
    bool metaballs_only_ = false;          // no metacube, no hard cube: the sweep compiles their cases out
    bool metaball_sweep_ = false;          // metaballs of a one-piece polynomial kernel: MetaballSweep applies
    BlobCells cells_;
};

}  // namespace isotrace
