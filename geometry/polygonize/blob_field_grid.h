#pragma once
// The summed field of a blob group at any point, found through a uniform grid of element supports.
//
// BlobGroup::field(index, p) needs an element whose support contains p; a polygoniser samples points that no
// ray query pointed it to, so it keeps its own lookup: every grid cell lists the elements whose support box
// overlaps it, and the field at p is the sum over the list of p's cell (every other element is zero at p).
#include <cstdint>
#include <vector>

#include "geometry/implicit/blob_group.h"

namespace isotrace {

class BlobFieldGrid {
public:
    // Keeps a reference: the group must outlive the grid.
    explicit BlobFieldGrid(const BlobGroup& group);

    // Σ wᵢ·fᵢ(P): the surface is where it equals group.threshold(), the inside where it is larger.
    double field(const Vec3d& point) const;
    // ∇ of field(point); −gradient is the outward normal direction.
    Vec3d gradient(const Vec3d& point) const;

private:
    struct ElementRange {
        std::uint32_t begin = 0, end = 0;
    };
    // The elements that may be non-zero at `point` (indices into group.elements()).
    ElementRange candidates(const Vec3d& point) const;
    bool within_reach(std::uint32_t element, const Vec3d& point) const {  // inline: called per candidate
        const Vec3d offset = point - reach_[element].centre;
        return dot(offset, offset) <= reach_[element].radius_squared;
    }

    // An element's bounding sphere (centre, (R + |half-size|)²): a test of a few flops that rejects most
    // candidates, which are zero at the point, before the full field evaluation.
    struct Reach {
        Vec3d centre;
        double radius_squared = 0;
    };

    const BlobGroup& group_;
    std::vector<Reach> reach_;  // per element
    Vec3d origin_;
    double cell_size_ = 1;
    std::vector<std::uint64_t> cell_keys_;     // sorted, one per non-empty cell
    std::vector<std::uint32_t> cell_offsets_;  // cell_keys_.size() + 1 offsets into cell_elements_
    std::vector<std::uint32_t> cell_elements_;
};

}  // namespace isotrace
