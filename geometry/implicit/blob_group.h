#pragma once
// BlobGroup: skeletal elements (metaballs and metacubes) whose fields add up, and the surface where the sum
// reaches the group's threshold: F(P) = Σ wᵢ·fᵢ(dist²ᵢ(P)) − T = 0, outward normal −∇F.
//
// Ray queries work per cell (blob_cells.h): space is cut into disjoint boxes, each listing the elements that
// reach into it, and a cell's stretch of a ray is marched once, front to back, by the cell queries (blob_ray.cpp,
// built for baseline x86-64 and for AVX2: blob_cell_queries.h), which read the group through its view. Cells are
// what Embree traverses (blob_group_shape.h); walking a ray's cells in order gives every crossing (CSG) or the first.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "geometry/implicit/blob_cells.h"
#include "geometry/implicit/blob_query_work.h"
#include "geometry/implicit/bounding_sphere.h"
#include "geometry/implicit/field_crossing.h"
#include "geometry/implicit/field_function.h"
#include "geometry/implicit/metacube.h"
#include "renderer/math/transform.h"

namespace isotrace {

struct BlobCellQueries;

// What a march reads of a group (blob_ray.cpp), as plain data: it is valid while the group is neither changed nor
// moved.
struct BlobGroupView {
    std::span<const Metacube> elements;
    std::span<const BoundingSphere> spheres;  // per element, for the march's first test
    double centre_bound;                      // the largest |centre| of the spheres (scales that test's margin)
    double threshold;
    const BlobCells& cells;
    const FieldFunction& kernel;
    std::size_t kernel_index;  // in FieldKernels (field_kernels.h), for with_kernel
    bool metaballs_only;       // no metacube, no hard cube: the march compiles their cases out
    bool metaball_march;       // metaballs of a one-piece polynomial kernel: MetaballMarch applies
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

    // What the ray queries read (blob_cell_queries.h), and the build of them chosen for this process when the group
    // was made.
    BlobGroupView view() const {
        return {elements_, spheres_, centre_bound_, threshold_, cells_, *kernel_, kernel_index_, metaballs_only_,
                metaball_march_};
    }
    const BlobCellQueries& queries() const { return *queries_; }
    // The first crossing along the whole ray, walking its cells in order.
    std::optional<FieldCrossing> first_crossing(const Vec3d& origin, const Vec3d& direction, double t_min,
                                                double t_max, BlobQueryWork& work) const;
    // Every crossing along o + t·d for t in (t_min, t_max) (finite), in increasing t; returns the sign of F at
    // t_min (+1 inside). For CSG.
    int crossings(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                  std::vector<FieldCrossing>& out, BlobQueryWork& work) const;

    // F(P) + T (the summed field) and its gradient.
    double field(const Vec3d& point) const;
    // field() at each of `points` into `sums` (as many slots), bit for bit, given `listed`: ascending, every element
    // whose support may reach one of the points. Element by element, so each point sums its terms in field()'s
    // order; for many points near each other (a block of lattice corners), which share one list.
    void fields(std::span<const std::uint32_t> listed, std::span<const Vec3d> points, std::span<double> sums) const;
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

    // The face of a hard cube (of those listed near the point, or of `listed`) whose plane lies nearest to it: the
    // cube, the face's outward unit normal and the distance to its plane. std::nullopt when there is no hard cube.
    struct HardCubeFace {
        std::uint32_t element;
        Vec3d normal;
        double gap;
    };
    std::optional<HardCubeFace> nearest_hard_cube_face(const Vec3d& point) const;
    std::optional<HardCubeFace> nearest_hard_cube_face_from(std::span<const std::uint32_t> listed,
                                                            const Vec3d& point) const;

    // Applies a similarity transform (rotation, uniform scale, translation; `scale` is its scale factor).
    void bake(const Transform& similarity, double scale);

private:
    void build_index();
    Vec3d normal_from(std::span<const std::uint32_t> near, const Vec3d& point) const;
    // ∇(F + T) from the `near` elements (a list that holds every element whose support contains the point).
    Vec3d gradient_from(std::span<const std::uint32_t> near, const Vec3d& point) const;
    // Calls visit(element) for the `listed` elements whose support may contain the point, in list order.
    template <class Visit>
    void for_each_reaching(std::span<const std::uint32_t> listed, const Vec3d& point, Visit&& visit) const;

    std::vector<Metacube> elements_;
    std::unique_ptr<const FieldFunction> kernel_;
    std::size_t kernel_index_;  // in FieldKernels
    const BlobCellQueries* queries_;
    double threshold_;
    std::vector<BoundingSphere> spheres_;  // per element, for the march's first test
    double centre_bound_ = 0;              // the largest |centre| of spheres_ (scales that test's float margin)
    bool metaballs_only_ = false;          // no metacube, no hard cube: the march compiles their cases out
    bool metaball_march_ = false;          // metaballs of a one-piece polynomial kernel: MetaballMarch applies
    BlobCells cells_;
};

}  // namespace isotrace
