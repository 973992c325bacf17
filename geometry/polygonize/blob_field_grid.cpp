#include "geometry/polygonize/blob_field_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace isotrace {
namespace {

constexpr std::int64_t kAxisMask = (std::int64_t(1) << 21) - 1;

std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
    return (std::uint64_t(x & kAxisMask) << 42) | (std::uint64_t(y & kAxisMask) << 21) | std::uint64_t(z & kAxisMask);
}

}  // namespace

BlobFieldGrid::BlobFieldGrid(const BlobGroup& group) : group_(group) {
    const std::vector<Metacube>& elements = group.elements();
    std::vector<WorldBounds> bounds(elements.size());
    origin_ = Vec3d(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity());
    Vec3d highest = -origin_;
    double extent_sum = 0;
    reach_.resize(elements.size());
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const double reach = elements[i].radius() + length(elements[i].skeleton().half_size);
        reach_[i] = {elements[i].skeleton().centre, reach * reach * (1 + 1e-9)};  // keeps boundary points in
        bounds[i] = elements[i].support_bounds();
        origin_ = min(origin_, bounds[i].lower);
        highest = max(highest, bounds[i].upper);
        extent_sum += max_component(bounds[i].upper - bounds[i].lower);
    }
    if (elements.empty()) return;
    // Cells of half the mean support size: a cell's list then holds few elements that are zero at a given point,
    // while an element is copied into about 27 cells. The lower limit keeps the cells within the 21-bit key.
    const double span = max_component(highest - origin_);
    cell_size_ = std::max({0.5 * extent_sum / double(elements.size()), span / double(kAxisMask - 1), 1e-300});

    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        std::int64_t lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::int64_t(std::floor((bounds[i].lower[k] - origin_[k]) / cell_size_));
            hi[k] = std::int64_t(std::floor((bounds[i].upper[k] - origin_[k]) / cell_size_));
        }
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
            for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
                for (std::int64_t z = lo[2]; z <= hi[2]; ++z) keyed.emplace_back(cell_key(x, y, z), std::uint32_t(i));
    }
    std::sort(keyed.begin(), keyed.end());
    cell_elements_.reserve(keyed.size());
    for (std::size_t i = 0; i < keyed.size(); ++i) {
        if (i == 0 || keyed[i].first != keyed[i - 1].first) {
            cell_keys_.push_back(keyed[i].first);
            cell_offsets_.push_back(std::uint32_t(i));
        }
        cell_elements_.push_back(keyed[i].second);
    }
    cell_offsets_.push_back(std::uint32_t(keyed.size()));
}

BlobFieldGrid::ElementRange BlobFieldGrid::candidates(const Vec3d& point) const {
    std::int64_t c[3];
    for (int k = 0; k < 3; ++k) {
        const double cell = std::floor((point[k] - origin_[k]) / cell_size_);
        if (!(cell >= 0 && cell <= double(kAxisMask))) return {};  // outside every support (or NaN)
        c[k] = std::int64_t(cell);
    }
    const std::uint64_t key = cell_key(c[0], c[1], c[2]);
    const auto found = std::lower_bound(cell_keys_.begin(), cell_keys_.end(), key);
    if (found == cell_keys_.end() || *found != key) return {};
    const std::size_t index = std::size_t(found - cell_keys_.begin());
    return {cell_offsets_[index], cell_offsets_[index + 1]};
}

double BlobFieldGrid::field(const Vec3d& point) const {
    const ElementRange range = candidates(point);
    double sum = 0;
    for (std::uint32_t i = range.begin; i < range.end; ++i)
        if (within_reach(cell_elements_[i], point)) sum += group_.elements()[cell_elements_[i]].field(group_.kernel(), point);
    return sum;
}

Vec3d BlobFieldGrid::gradient(const Vec3d& point) const {
    const ElementRange range = candidates(point);
    Vec3d sum(0, 0, 0);
    for (std::uint32_t i = range.begin; i < range.end; ++i)
        if (within_reach(cell_elements_[i], point))
            sum += group_.elements()[cell_elements_[i]].field_gradient(group_.kernel(), point);
    return sum;
}

}  // namespace isotrace
