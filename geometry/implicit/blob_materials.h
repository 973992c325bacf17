#pragma once
// The materials of a blob group's elements, and how they blend where the elements' fields meet.
//
// Part 0 is every element without a material of its own (it shows the object's material); each distinct name an
// element gives is one more part (Shape::part_materials). At a point P each part's share is the sum of its
// elements' terms wⱼ·fⱼ(P), taken as 0 where that sum is negative (carving elements give no material). The four
// largest shares are kept, largest first, and divided by their sum: what the other parts held is dropped, which is
// the same as sharing it among the four in proportion. The weights are then rounded to multiples of 2⁻²⁰, the
// largest taking the difference, so that they are ≥ 0 and add up to exactly 1 in float in any order.
//
// A hard cube's field is a step (w on its closed box, 0 outside), and a surface point on its face lies on either
// side of the face by rounding: it counts with its weight w at points within 10⁻⁵·(its half diagonal + the point's
// largest coordinate) of its box. Where no part has a positive share (rounding at the very edge of the supports),
// the point takes the part of the nearest element whole.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/implicit/blob_group.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

class BlobMaterials {
public:
    BlobMaterials() = default;  // no element has a material of its own
    // parts[0] has no name; element_parts holds each element's part. Throws std::invalid_argument when a part is
    // out of range or parts[0] has a name.
    BlobMaterials(std::vector<MaterialReference> parts, std::vector<std::uint32_t> element_parts);

    bool empty() const { return element_parts_.empty(); }
    // Empty when no element has a material of its own (the group then shows the object's material alone).
    const std::vector<MaterialReference>& parts() const { return parts_; }
    const std::vector<std::uint32_t>& element_parts() const { return element_parts_; }
    std::size_t memory_bytes() const { return element_parts_.capacity() * sizeof(std::uint32_t); }

    // The blend at P of the `listed` elements of `group` (a cell's, or those near P), whose elements these are.
    MaterialBlend blend(const BlobGroup& group, std::span<const std::uint32_t> listed, const Vec3d& point) const;

private:
    std::vector<MaterialReference> parts_;
    std::vector<std::uint32_t> element_parts_;
};

}  // namespace isotrace
