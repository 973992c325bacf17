#pragma once
// The part of a box where the surface of a blob group, Σ wᵢ·fᵢ = T, can lie. Each element's field is bounded over
// a sub-box from its nearest and farthest squared distance there (the kernel is non-increasing in dist²); where
// the summed bounds stay above T or below T the whole sub-box is inside or outside, and no ray crosses the surface
// there. The box is halved along its longest side, recursively, and the region returned is the bounding box of
// the finest sub-boxes whose bounds straddle T.
//
// Blob cells use it as their Embree bounds and as the stretch a ray sweeps: a ray that passes a cell where it is
// all inside, all outside or only near the surface costs Embree a box test and no query at all.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "geometry/implicit/metacube.h"

namespace isotrace {

namespace surface_region_detail {

// Halvings of the box: 4 leaves sub-boxes a half to a quarter of the cell per side. Measured on blobs_10k
// (callgrind, 115,200 primary rays at 320×180, build included): 4, 5 and 6 halvings execute 859.6 M, 857.0 M and
// 844.9 M instructions in the blob callback but 1.52 G, 1.60 G and 1.71 G in all, each halving more costing
// about as much build as it saves in a million rays.
constexpr int kHalvings = 4;
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

// Kernel is the concrete FieldFunction class (direct calls).
template <class Kernel>
class RegionSearch {
public:
    RegionSearch(std::span<const Metacube> elements, const Kernel& kernel, double threshold, std::size_t listed)
        : elements_(elements), kernel_(kernel), threshold_(threshold), per_level_(listed), lists_(new std::uint32_t[(kHalvings + 1) * listed]) {}

    // `ids` are the elements that may reach `box`; each level keeps those that do in its own part of lists_.
    void visit(const WorldBounds& box, std::span<const std::uint32_t> ids, int halvings) {
        if (region_ && contains(*region_, box)) return;  // nothing left to add
        std::uint32_t* reaching = lists_.get() + std::size_t(halvings) * per_level_;
        std::size_t count = 0;
        double low = 0, high = 0, scale = threshold_;
        for (std::uint32_t id : ids) {
            const Metacube& element = elements_[id];
            const double near2 = element.nearest_squared_distance(box);
            const double radius2 = element.radius() * element.radius();
            if (element.is_hard_cube() ? near2 > 0 : near2 >= radius2) continue;  // its support misses the box
            reaching[count++] = id;
            // The unweighted field at the nearest and at the farthest point. A hard cube's step is on its boundary,
            // which may be a face of the box (its cell is often the cube itself): the field just beyond counts,
            // so its weakest value is 0 even where the box lies in the closed cube.
            const double far2 = element.farthest_squared_distance(box);
            const double strongest = element.is_hard_cube() ? 1 : kernel_.unit_value(near2 / radius2);
            const double weakest = !element.is_hard_cube() && far2 < radius2 ? kernel_.unit_value(far2 / radius2) : 0;
            const double w = element.weight();
            low += w * (w >= 0 ? weakest : strongest);
            high += w * (w >= 0 ? strongest : weakest);
            scale += std::abs(w);
        }
        const double margin = kRelativeMargin * scale;
        if (high < threshold_ - margin || low > threshold_ + margin) return;
        if (halvings == kHalvings) {
            region_ = region_ ? WorldBounds{min(region_->lower, box.lower), max(region_->upper, box.upper)} : box;
            return;
        }
        const int axis = longest_axis(box.upper - box.lower);
        WorldBounds below = box, above = box;
        below.upper[axis] = above.lower[axis] = 0.5 * (box.lower[axis] + box.upper[axis]);
        visit(below, {reaching, count}, halvings + 1);
        visit(above, {reaching, count}, halvings + 1);
    }

    const std::optional<WorldBounds>& region() const { return region_; }

private:
    std::span<const Metacube> elements_;
    const Kernel& kernel_;
    double threshold_;
    std::size_t per_level_;
    std::unique_ptr<std::uint32_t[]> lists_;  // not zeroed: each level writes before it reads
    std::optional<WorldBounds> region_;
};

}  // namespace surface_region_detail

// std::nullopt when the surface provably misses `box`. `ids` lists every element (of `elements`) whose support
// reaches into the box. The region stays inside `box`. Kernel is the concrete FieldFunction class.
template <class Kernel>
std::optional<WorldBounds> surface_region(const WorldBounds& box, std::span<const std::uint32_t> ids,
                                          std::span<const Metacube> elements, const Kernel& kernel,
                                          double threshold) {
    using namespace surface_region_detail;
    RegionSearch<Kernel> search(elements, kernel, threshold, ids.size());
    search.visit(box, ids, 0);
    if (!search.region()) return std::nullopt;
    const Vec3d padding = (box.upper - box.lower) * kRelativePadding;
    return WorldBounds{max(search.region()->lower - padding, box.lower),
                       min(search.region()->upper + padding, box.upper)};
}

}  // namespace isotrace
