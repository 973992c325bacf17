#pragma once
// The part of a box where the surface of a blob group, Σ wᵢ·fᵢ = T, can lie. Each element's field is bounded over
// a sub-box from its nearest and farthest squared distance there (the kernel is non-increasing in dist²); where
// the summed bounds stay above T or below T the whole sub-box is inside or outside, and no ray crosses the surface
// there. The box is halved along its longest side, recursively, and the region returned is the bounding box of
// the finest sub-boxes whose bounds straddle T.
//
// Blob cells use it as their Embree bounds and as the stretch a ray marches: a ray that passes a cell where it is
// all inside, all outside or only near the surface costs Embree a box test and no query at all.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "geometry/implicit/field_function.h"
#include "geometry/implicit/metacube.h"
#include "renderer/math/double4.h"

namespace isotrace {

namespace surface_region_detail {

// Halvings of the box: 12 leave sub-boxes of a sixteenth of the cell per side. The finer the region, the fewer the
// rays that enter a cell's box without meeting the surface (each a query the candidates' bound ends at once); more
// halvings gain nothing, and each costs build time (docs/decisions.md, "Blob groups: cells shrunk to where the surface
// can be").
constexpr int kHalvings = 12;
// The sums are rounded; a sub-box whose bounds miss T by less than this (relative to the field's scale) is kept,
// so rounding never drops a sub-box the surface touches.
constexpr double kRelativeMargin = 1e-9;
// The region grows by this fraction of the box on each side (clamped to the box): a root finder's crossing on
// the region's face must not fall outside it by a rounding error.
constexpr double kRelativePadding = 1e-7;

inline bool contains(const WorldBounds& outer, const WorldBounds& inner) {
    for (int k = 0; k < 3; ++k)
        if (inner.lower[k] < outer.lower[k] || inner.upper[k] > outer.upper[k]) return false;
    return true;
}

// Bounds of Σ wᵢ·fᵢ over a box, and Σ |wᵢ| (with T: the scale of their rounding).
struct FieldBounds {
    double low = 0, high = 0, scale = 0;
};

// A cell's elements by index, of any kind and kernel (Kernel: the concrete FieldFunction class, called directly).
// Level h holds the elements that may reach the sub-box visited after h halvings.
template <class Kernel>
class ListedElements {
public:
    ListedElements(std::span<const Metacube> elements, const Kernel& kernel, std::span<const std::uint32_t> ids)
        : elements_(elements), kernel_(kernel), per_level_(ids.size()), ids_((kHalvings + 2) * ids.size()),
          counts_(kHalvings + 2) {
        std::copy(ids.begin(), ids.end(), ids_.begin());
        counts_[0] = ids.size();
    }

    // The bounds over `box` of level h's elements; those that reach it become level h + 1.
    FieldBounds bounds(const WorldBounds& box, int h) {
        const std::uint32_t* listed = ids_.data() + std::size_t(h) * per_level_;
        std::uint32_t* reaching = ids_.data() + std::size_t(h + 1) * per_level_;
        std::size_t count = 0;
        FieldBounds sum;
        for (std::size_t i = 0; i < counts_[std::size_t(h)]; ++i) {
            const Metacube& element = elements_[listed[i]];
            const double near2 = element.nearest_squared_distance(box);
            const double radius2 = element.radius() * element.radius();
            if (element.is_hard_cube() ? near2 > 0 : near2 >= radius2) continue;  // its support misses the box
            reaching[count++] = listed[i];
            // The unweighted field at the nearest and at the farthest point. A hard cube's step is on its boundary,
            // which may be a face of the box (its cell is often the cube itself): the field just beyond counts,
            // so its weakest value is 0 even where the box lies in the closed cube.
            const double far2 = element.farthest_squared_distance(box);
            const double strongest = element.is_hard_cube() ? 1 : kernel_.unit_value(near2 / radius2);
            const double weakest = !element.is_hard_cube() && far2 < radius2 ? kernel_.unit_value(far2 / radius2) : 0;
            const double w = element.weight();
            sum.low += w * (w >= 0 ? weakest : strongest);
            sum.high += w * (w >= 0 ? strongest : weakest);
            sum.scale += std::abs(w);
        }
        counts_[std::size_t(h + 1)] = count;
        return sum;
    }

private:
    std::span<const Metacube> elements_;
    const Kernel& kernel_;
    std::size_t per_level_;
    std::vector<std::uint32_t> ids_;  // per level, per_level_ entries
    std::vector<std::size_t> counts_;
};

// Metaballs alone under a kernel that is one polynomial of degree ≤ 3 in x = dist²/R² on [0, 1] and 0 beyond
// (Kim's, Wyvill's, Murakami's: the benchmark clouds), four at a time, from their centres, 1/R² and weights in lanes,
// with no branch per element: the bounds of ListedElements to rounding, 2.4 times as fast (blobs_100k's regions:
// 2.9 s on 2 threads element by element).
class MetaballLanes {
public:
    MetaballLanes(std::span<const Metacube> elements, const FieldPiece& unit, std::span<const std::uint32_t> ids);
    FieldBounds bounds(const WorldBounds& box, int h);

private:
    enum Field { kX, kY, kZ, kInverseRadius2, kWeight, kFields };
    // Level h's lanes of one field: its own storage, or that of the level before when every element reached.
    double* lanes(int h, Field field) {
        return lanes_.get() + (levels_[std::size_t(h)] * kFields + field) * per_level_;
    }
    // Lanes [first, end of its group) of level h: weight 0 and 1/R² = ∞, so that they never reach a sub-box.
    void make_inert(int h, std::size_t first);

    std::array<double, 4> coefficients_;
    std::size_t per_level_;             // the cell's element count, rounded up to whole groups of four
    std::unique_ptr<double[]> lanes_;   // per level of storage, per field, per_level_ lanes (each written before read)
    std::vector<std::size_t> counts_;   // per level: its elements; the lanes after them, to a whole group, are inert
    std::vector<std::size_t> levels_;   // per level, the level whose storage holds its lanes
    std::vector<unsigned> reaching_;    // per group of the level being bounded, its lanes that reach the sub-box
};

// The bounding box of the finest sub-boxes of `box` whose bounds straddle T, if any; a sub-box that the region
// found so far contains is not examined (it cannot grow it).
template <class Elements>
std::optional<WorldBounds> straddling_bounds(Elements& elements, const WorldBounds& box, double threshold) {
    std::optional<WorldBounds> region;
    const auto visit = [&](const auto& self, const WorldBounds& sub_box, int h) -> void {
        if (region && contains(*region, sub_box)) return;  // nothing left to add
        const FieldBounds sum = elements.bounds(sub_box, h);
        const double margin = kRelativeMargin * (threshold + sum.scale);
        if (sum.high < threshold - margin || sum.low > threshold + margin) return;
        if (h == kHalvings) {
            region = region ? WorldBounds{min(region->lower, sub_box.lower), max(region->upper, sub_box.upper)}
                            : sub_box;
            return;
        }
        const int axis = longest_axis(sub_box.upper - sub_box.lower);
        WorldBounds below = sub_box, above = sub_box;
        below.upper[axis] = above.lower[axis] = 0.5 * (sub_box.lower[axis] + sub_box.upper[axis]);
        self(self, below, h + 1);
        self(self, above, h + 1);
    };
    visit(visit, box, 0);
    return region;
}

// The region, padded and clamped to `box`.
std::optional<WorldBounds> padded_region(const std::optional<WorldBounds>& region, const WorldBounds& box);

}  // namespace surface_region_detail

// std::nullopt when the surface provably misses `box`. `ids` lists every element (of `elements`) whose support
// reaches into the box. The region stays inside `box`. Kernel is the concrete FieldFunction class.
template <class Kernel>
std::optional<WorldBounds> surface_region(const WorldBounds& box, std::span<const std::uint32_t> ids,
                                          std::span<const Metacube> elements, const Kernel& kernel,
                                          double threshold) {
    using namespace surface_region_detail;
    ListedElements<Kernel> listed(elements, kernel, ids);
    return padded_region(straddling_bounds(listed, box, threshold), box);
}

// The same region where every element is a metaball and the kernel is `unit`, one polynomial piece of degree ≤ 3 on
// x = dist²/R² ∈ [0, 1) and 0 beyond (MetaballMarch::applies), in lanes.
std::optional<WorldBounds> metaball_surface_region(const WorldBounds& box, std::span<const std::uint32_t> ids,
                                                   std::span<const Metacube> elements, const FieldPiece& unit,
                                                   double threshold);

}  // namespace isotrace
