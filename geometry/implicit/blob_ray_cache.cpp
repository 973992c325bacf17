#include "geometry/implicit/blob_ray_cache.h"

#include <algorithm>

#include "geometry/implicit/blob_group.h"

namespace isotrace {

void BlobRayCache::begin(const BlobGroup& group, const Vec3d& origin, const Vec3d& direction, double t_min) {
    if (&group == group_ && group.identity() == group_identity_ && origin == origin_ && direction == direction_ &&
        t_min == t_min_)
        return;
    group_ = &group;
    group_identity_ = group.identity();
    origin_ = origin;
    direction_ = direction;
    t_min_ = t_min;
    ++generation_;
    overflow_.clear();
    settled_.clear();
}

const MetacubeRaySlices* BlobRayCache::slices(std::uint32_t element) {
    const auto compute = [&] { return MetacubeRaySlices::slice(group_->elements()[element], origin_, direction_); };
    std::size_t slot = (element * 2654435761u) & (kSlots - 1);
    for (int probe = 0; probe < 8; ++probe, slot = (slot + 1) & (kSlots - 1)) {
        Entry& entry = table_[slot];
        if (entry.generation == generation_ && entry.element == element)
            return entry.slices ? &*entry.slices : nullptr;
        if (entry.generation != generation_) {
            entry.generation = generation_;
            entry.element = element;
            entry.slices = compute();
            return entry.slices ? &*entry.slices : nullptr;
        }
    }
    const auto& slices = overflow_.emplace_back(compute());
    return slices ? &*slices : nullptr;
}

std::optional<BlobRayCache::Settled> BlobRayCache::settled_at(double t) const {
    for (const Settled& s : settled_)
        if (s.lo <= t && t < s.hi) return s;
    return std::nullopt;
}

std::optional<BlobRayCache::Settled> BlobRayCache::settled_before(double t) const {
    for (const Settled& s : settled_)
        if (s.lo < t && t <= s.hi) return s;
    return std::nullopt;
}

void BlobRayCache::settle(double lo, double hi, int sign) {
    if (!(lo < hi)) return;
    // Merge with every stretch of the same sign that overlaps or touches; stretches of opposite sign cannot
    // overlap a settled one (the field has one sign there), they can only touch it at a crossing.
    Settled merged{lo, hi, sign};
    std::erase_if(settled_, [&](const Settled& s) {
        if (s.sign != sign || s.hi < merged.lo || s.lo > merged.hi) return false;
        merged.lo = std::min(merged.lo, s.lo);
        merged.hi = std::max(merged.hi, s.hi);
        return true;
    });
    settled_.insert(std::upper_bound(settled_.begin(), settled_.end(), merged,
                                     [](const Settled& x, const Settled& y) { return x.lo < y.lo; }),
                    merged);
}

BlobRayCache& BlobRayCache::for_this_thread() {
    thread_local BlobRayCache cache;
    return cache;
}

}  // namespace isotrace
